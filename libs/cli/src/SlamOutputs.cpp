#include <sys/resource.h>

#include <whiskermap/cli/SlamOutputs.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/render/TopDownImage.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace whiskermap::cli
{
namespace
{
using mrpt::img::TColor;
using Path = std::vector<world::PathLog::Entry>;
const TColor TRUTH(0, 0, 200), ESTIMATE(200, 40, 40), ODOMETRY(230, 140, 0), MAP(120, 120, 120);

void writePath(OutputDir& out, const std::string& name, const std::string& title, const Path& path)
{
	world::PathLog::Writer w(out.path(name), title);
	for (const auto& e : path) w.write(e.t, e.pose);
	w.close();
}

std::vector<mrpt::poses::CPose2D> poses(const Path& path)
{
	std::vector<mrpt::poses::CPose2D> out;
	for (const auto& e : path) out.push_back(e.pose);
	return out;
}

double quantile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[static_cast<size_t>(std::floor(q * (v.size() - 1) + 0.5))];
}

/** {"trajectory": {...}} of whisker-eval --json, for `est` against the truth. */
std::string trajectoryJson(const Path& est, const Path& truth, const std::string& label, const std::string& truthLabel)
{
	eval::EvalReport r;
	r.trajectory = eval::TrajectoryEvaluation::compute(est, truth, r.options, label, truthLabel);
	std::string json = r.toJson();
	return json.substr(0, json.find_last_not_of('\n') + 1);
}

void drawPaths(OutputDir& out, const SlamOutputs::TRun& run, const MapOutputs::TSettings& s)
{
	render::TopDownImage img(s.x0, s.x1, s.y0, s.y1);
	if (s.world) img.arena(*s.world, {0, 0, 0});
	if (s.world)
		for (const auto& t : s.world->tables) img.table(t, TRUTH, 1);
	for (const auto& t : run.mapTables) img.table(t, MAP, 2);
	img.path(poses(run.odometry), ODOMETRY, 1);
	if (run.truth) img.path(poses(*run.truth), TRUTH, 1);
	img.path(poses(run.estimated), ESTIMATE, 2);
	img.caption(std::filesystem::path(run.input).filename().string() + ": paths and the best particle's map");
	img.caption(std::string("SLAM (red), odometry (orange)") + (run.truth ? ", truth (blue)" : "") + ", map (grey)" +
				(s.world ? ", true tables" : ""));
	img.save(out.path("paths.png"));
}

void writeSummary(const std::string& path, const SlamOutputs::TRun& run)
{
	const auto& steps = run.slam->steps();
	std::vector<double> ms;
	size_t resamplings = 0;
	double total = 0, minEss = 1;
	for (const auto& st : steps)
		ms.push_back(st.ms), total += st.ms, resamplings += st.resampled, minEss = std::min(minEss, st.ess);
	rusage usage{};
	::getrusage(RUSAGE_SELF, &usage);
	const auto& p = *run.params;
	std::ofstream f(path);
	char buf[512];
	f << "{\n  \"input\": \"" << run.input << "\",\n  \"config\": \"" << run.config << "\",\n";
	f << "  \"map_config\": \"" << run.mapConfig << "\",\n";
	f << "  \"particles\": " << p.particles << ",\n  \"seed\": " << p.seed << ",\n  \"sweeps\": " << steps.size()
	  << ",\n";
	std::snprintf(buf, sizeof(buf),
				  "  \"time_per_step_ms\": {\"mean\": %.4f, \"median\": %.4f, \"p95\": %.4f, \"max\": %.4f},\n",
				  steps.empty() ? 0.0 : total / steps.size(), quantile(ms, 0.5), quantile(ms, 0.95), quantile(ms, 1));
	f << buf;
	std::snprintf(buf, sizeof(buf), "  \"resample_ess\": %.4f,\n  \"resamplings\": %zu,\n  \"ess_min\": %.6f,\n",
				  p.resample_ess, resamplings, minEss);
	f << buf;
	f << "  \"ess\": [";  // normalised ESS before resampling, one per sweep
	for (size_t i = 0; i < steps.size(); i++)
	{
		std::snprintf(buf, sizeof(buf), "%s%.4f", i ? (i % 16 ? ", " : ",\n    ") : "", steps[i].ess);
		f << buf;
	}
	f << "],\n  \"map_tables\": " << run.mapTables.size() << ",\n";
	f << "  \"map_matches_best_particle\": " << (run.mapMatches ? "true" : "false") << ",\n";
	if (run.truth)
	{
		f << "  \"truth\": \"" << run.truthPath << "\",\n";
		f << "  \"estimated\": " << trajectoryJson(run.estimated, *run.truth, "estimated path", run.truthPath) << ",\n";
		f << "  \"odometry\": " << trajectoryJson(run.odometry, *run.truth, "odometry path", run.truthPath) << ",\n";
	}
	std::snprintf(buf, sizeof(buf), "  \"wall_time_s\": %.3f,\n  \"peak_rss_mb\": %.1f\n}\n", run.wallSeconds,
				  usage.ru_maxrss / 1024.0);
	f << buf;
	if (!f) throw core::Error(path + ": write failed");
}
}  // namespace

std::string SlamOutputs::write(OutputDir& out, const TRun& run, const MapOutputs::TSettings& picture)
{
	writePath(out, "estimated_path.txt", "whisker-slam: the best particle's path, one pose per sweep", run.estimated);
	writePath(out, "odometry_path.txt", "whisker-slam: the odometry of each sweep, as read from the rawlog", run.odometry);
	drawPaths(out, run, picture);
	writeSummary(out.path("summary.json"), run);
	char line[256];
	std::snprintf(line, sizeof(line), "%zu sweeps, %u particles, %zu tables", run.estimated.size(),
				  run.params->particles, run.mapTables.size());
	std::string text = line;
	if (run.truth)
	{
		const eval::EvalOptions o;
		const auto e = eval::TrajectoryEvaluation::compute(run.estimated, *run.truth, o);
		const auto d = eval::TrajectoryEvaluation::compute(run.odometry, *run.truth, o);
		std::snprintf(line, sizeof(line), "; ATE RMSE %.3f m (aligned %.3f), odometry %.3f m (aligned %.3f)",
					  e.ate_rmse_m, e.aligned_rmse_m, d.ate_rmse_m, d.aligned_rmse_m);
		text += line;
	}
	return text;
}
}  // namespace whiskermap::cli
