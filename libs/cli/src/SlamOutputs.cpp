#include <whiskermap/cli/SlamOutputs.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/peakRssMb.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/render/TopDownImage.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace whiskermap::cli
{
namespace
{
using mrpt::img::TColor;
const TColor TRUTH(0, 0, 200), ESTIMATE(200, 40, 40), FILTER(240, 150, 190), ODOMETRY(230, 140, 0), MAP(120, 120, 120);

/** The first `n` poses of a path file, an even subset of at most 20,000 (the picture's). */
std::vector<mrpt::poses::CPose2D> picturePoses(const std::string& file, size_t n)
{
	Decimator<mrpt::poses::CPose2D> kept(20000);
	world::PathLog::Reader r(file);
	for (world::PathLog::Entry e; r.count() < n && r.next(e);) kept.add(mrpt::poses::CPose2D(e.pose));
	return kept.items();
}

double quantile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[static_cast<size_t>(std::floor(q * (v.size() - 1) + 0.5))];
}

/** {"trajectory": {...}} of whisker-eval --json. */
nlohmann::ordered_json trajectoryJson(const eval::TrajectoryEvaluation& t)
{
	eval::EvalReport r;
	r.trajectory = t;
	return nlohmann::ordered_json::parse(r.toJson());
}

void drawPaths(OutputDir& out, const SlamOutputs::TRun& run, const MapOutputs::TSettings& s)
{
	render::TopDownImage img(s.x0, s.x1, s.y0, s.y1);
	if (s.world) img.arena(*s.world, {0, 0, 0});
	if (s.world)
		for (const auto& t : s.world->tables) img.table(t, TRUTH, 1);
	for (const auto& t : run.mapTables) img.table(t, MAP, 2);
	img.path(picturePoses(run.odometryFile, run.sweeps), ODOMETRY, 1);
	if (!run.truthPath.empty()) img.path(picturePoses(run.truthPath, run.sweeps), TRUTH, 1);
	if (run.smoothing && !run.filterFile.empty()) img.path(picturePoses(run.filterFile, run.sweeps), FILTER, 1);
	img.path(picturePoses(run.estimatedFile, run.sweeps), ESTIMATE, 2);
	const std::string what = run.oracle ? "oracle (red)"
						   : run.smoothing ? "SLAM smoothed (red), best particle (pink)"
										   : "SLAM (red)";
	img.caption(std::filesystem::path(run.input).filename().string() + ": paths and the map at the " +
				(run.oracle ? "oracle's path" : run.smoothing ? "smoothed path" : "best particle's path (its own map)"));
	img.caption(what + ", odometry (orange)" + (run.truthPath.empty() ? "" : ", truth (blue)") + ", map (grey)" +
				(s.world ? ", true tables (blue)" : ""));
	img.save(out.path("paths.png"));
}

struct Scores
{
	eval::TrajectoryEvaluation estimated, odometry;
	std::optional<eval::TrajectoryEvaluation> filter;  ///< none without a filter (oracle)
};

void writeSummary(const std::string& path, const SlamOutputs::TRun& run, const std::optional<Scores>& scores)
{
	const auto& st = run.steps;
	nlohmann::ordered_json ess = nlohmann::ordered_json::array();  // normalised ESS before resampling
	for (const double e : st.ess.items()) ess.push_back(std::round(e * 1e4) / 1e4);
	const auto& p = *run.params;
	nlohmann::ordered_json j;  // a JSON writer: any path (quotes, backslashes) stays valid JSON
	j["input"] = run.input, j["config"] = run.config, j["map_config"] = run.mapConfig, j["oracle"] = run.oracle;
	j["particles"] = run.particles, j["particles_config"] = p.particles, j["seed"] = p.seed, j["sweeps"] = run.sweeps;
	j["time_per_step_ms"] = {
		{"mean", st.count ? st.totalMs / st.count : 0.0},
		{"median", quantile(st.ms.items(), 0.5)},
		{"p95", quantile(st.ms.items(), 0.95)},
		{"max", st.maxMs}};
	j["proposal_samples"] = p.proposal_samples, j["batch_sweeps"] = p.batch_sweeps;
	j["manhattan_walls"] = p.manhattan_walls, j["wall_extension"] = p.wall_extension, j["leg_merge_gap"] = p.leg_merge_gap;
	j["disjoint_tables"] = p.disjoint_tables;
	j["resample_ess"] = p.resample_ess, j["resamplings"] = st.resamplings, j["ess_min"] = st.minEss;
	j["ess_stride"] = st.ess.stride();
	j["ess"] = std::move(ess);
	j["path_poses_max"] = st.pathPosesMax;
	j["map_tables"] = run.mapTables.size();
	j["map_matches_best_particle"] = run.mapMatches ? nlohmann::json(*run.mapMatches) : nlohmann::json();  // null: smoothed
	if (const auto* sm = run.smoothing)
		j["smoothing"] = {
			{"contacts_tied", sm->tied}, {"duplicate_legs", sm->duplicates}, {"duplicate_legs_apart", sm->duplicatesApart},
			{"duplicate_walls", sm->duplicateWalls}, {"duplicate_walls_apart", sm->duplicateWallsApart},
			{"stretches", sm->stretches}, {"stretches_tried", sm->stretchesTried},
			{"bridges", sm->bridges}, {"bridges_tried", sm->bridgesTried}, {"stray_max", sm->strayMax},
			{"cost_before", sm->costBefore}, {"cost_after", sm->costAfter}, {"rounds", sm->rounds},
			{"iterations", sm->iterations}, {"seconds", run.smoothingSeconds}};
	else
		j["smoothing"] = nullptr;
	if (scores)
	{
		j["truth"] = run.truthPath;
		j["estimated"] = trajectoryJson(scores->estimated);
		j["odometry"] = trajectoryJson(scores->odometry);
		if (scores->filter) j["filter"] = trajectoryJson(*scores->filter);
	}
	j["wall_time_s"] = run.wallSeconds;
	j["peak_rss_mb"] = core::peakRssMb();
	j["filter_peak_rss_mb"] = {{"first_tenth", run.filterRssTenthMb}, {"end", run.filterRssMb}};
	const auto known = [](double mb) { return std::isnan(mb) ? nlohmann::json() : nlohmann::json(mb); };  // null: not measured
	j["filter_heap_mb"] = {{"first_tenth", known(run.filterHeapTenthMb)}, {"end", known(run.filterHeapMb)}};
	const auto maps = [](const slam::RbpfSlam::TMapTotals& t) {
		return nlohmann::json{{"tables", t.tables}, {"legs", t.legs}, {"legs_without_table", t.legsWithoutTable},
							  {"legs_beside", t.legsBeside}, {"walls", t.walls},
							  {"contacts_explained", t.explained}, {"contacts_unexplained", t.unexplained},
							  {"swept_chunks", t.sweptChunks}, {"swept_chunks_shared", t.sharedChunks},
							  {"lasting_chunks", t.lastingChunks}, {"lasting_chunks_shared", t.lastingShared}};
	};
	j["filter_maps"] = {{"first_tenth", maps(run.filterMapsTenth)}, {"end", maps(run.filterMaps)}};
	std::ofstream f(path);
	f << j.dump(2) << "\n";
	if (!f) throw core::Error(path + ": write failed");
}
}  // namespace

std::string SlamOutputs::write(OutputDir& out, const TRun& run, const MapOutputs::TSettings& picture)
{
	std::optional<Scores> scores;
	if (!run.truthPath.empty())
	{
		// Streamed from the files: what whisker-eval --path FILE --truth TRUTH reports.
		const eval::EvalOptions o;
		scores = Scores{
			eval::TrajectoryEvaluation::compute(run.estimatedFile, run.truthPath, o, run.sweeps),
			eval::TrajectoryEvaluation::compute(run.odometryFile, run.truthPath, o, run.sweeps), std::nullopt};
		if (!run.filterFile.empty())
			scores->filter = eval::TrajectoryEvaluation::compute(run.filterFile, run.truthPath, o, run.sweeps);
	}
	drawPaths(out, run, picture);
	writeSummary(out.path("summary.json"), run, scores);
	char line[256];
	if (run.oracle)
		std::snprintf(line, sizeof(line), "%zu sweeps, oracle, %zu tables", run.sweeps, run.mapTables.size());
	else
		std::snprintf(line, sizeof(line), "%zu sweeps, %zu particle%s, %zu tables", run.sweeps, run.particles,
					  run.particles == 1 ? "" : "s", run.mapTables.size());
	std::string text = line;
	if (scores)
	{
		const auto &e = scores->estimated, &d = scores->odometry;
		std::snprintf(line, sizeof(line), "; ATE RMSE %.3f m (aligned %.3f", e.ate_rmse_m, e.aligned_rmse_m);
		text += line;
		if (scores->filter)
			std::snprintf(line, sizeof(line), "; best particle %.3f", scores->filter->ate_rmse_m), text += line;
		std::snprintf(line, sizeof(line), "), odometry %.3f m (aligned %.3f)", d.ate_rmse_m, d.aligned_rmse_m);
		text += line;
	}
	return text;
}
}  // namespace whiskermap::cli
