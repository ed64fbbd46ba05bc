#include <sys/resource.h>

#include <whiskermap/cli/SlamOutputs.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/render/TopDownImage.h>

#include <nlohmann/json.hpp>

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
	for (const auto& e : path) w.write(e.t, mrpt::poses::CPose2D(e.pose));
	w.close();
}

std::vector<mrpt::poses::CPose2D> poses(const Path& path)
{
	std::vector<mrpt::poses::CPose2D> out;
	for (const auto& e : path) out.emplace_back(e.pose);
	return out;
}

double quantile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[static_cast<size_t>(std::floor(q * (v.size() - 1) + 0.5))];
}

/** {"trajectory": {...}} of whisker-eval --json, for `est` against the truth. */
nlohmann::ordered_json trajectoryJson(
	const Path& est, const Path& truth, const std::string& label, const std::string& truthLabel)
{
	eval::EvalReport r;
	r.trajectory = eval::TrajectoryEvaluation::compute(est, truth, r.options, label, truthLabel);
	return nlohmann::ordered_json::parse(r.toJson());
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
	nlohmann::ordered_json ess = nlohmann::ordered_json::array();  // normalised ESS before resampling, per sweep
	size_t resamplings = 0;
	double total = 0, minEss = 1;
	for (const auto& st : steps)
	{
		ms.push_back(st.ms), total += st.ms, resamplings += st.resampled, minEss = std::min(minEss, st.ess);
		ess.push_back(std::round(st.ess * 1e4) / 1e4);
	}
	rusage usage{};
	::getrusage(RUSAGE_SELF, &usage);
	const auto& p = *run.params;
	nlohmann::ordered_json j;  // a JSON writer: any path (quotes, backslashes) stays valid JSON
	j["input"] = run.input, j["config"] = run.config, j["map_config"] = run.mapConfig;
	j["particles"] = p.particles, j["seed"] = p.seed, j["sweeps"] = steps.size();
	j["time_per_step_ms"] = {
		{"mean", steps.empty() ? 0.0 : total / steps.size()},
		{"median", quantile(ms, 0.5)},
		{"p95", quantile(ms, 0.95)},
		{"max", quantile(ms, 1)}};
	j["resample_ess"] = p.resample_ess, j["resamplings"] = resamplings, j["ess_min"] = minEss;
	j["ess"] = std::move(ess);
	j["map_tables"] = run.mapTables.size();
	j["map_matches_best_particle"] = run.mapMatches;
	if (run.truth)
	{
		j["truth"] = run.truthPath;
		j["estimated"] = trajectoryJson(run.estimated, *run.truth, "estimated path", run.truthPath);
		j["odometry"] = trajectoryJson(run.odometry, *run.truth, "odometry path", run.truthPath);
	}
	j["wall_time_s"] = run.wallSeconds;
	j["peak_rss_mb"] = usage.ru_maxrss / 1024.0;
	std::ofstream f(path);
	f << j.dump(2) << "\n";
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
