#include <unistd.h>

#include <CLI/CLI.hpp>
#include <whiskermap/cli/MapOutputs.h>
#include <whiskermap/cli/MapRunner.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/cli/WhiskerMapApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/render/OcTreeExport.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <thread>

namespace whiskermap::cli
{
namespace
{
struct Options
{
	std::string input, config, outdir, world, mode;
	std::optional<uint64_t> seed;
	int snapshotPose = -1, snapshotTemperature = 0;
	unsigned jobs = 1;
	bool quiet = false, simpleMap = false, reverse = false;
};

/** Tables lie within whisker reach of the robot: refuse early a log whose map could not be
 *  exported as an OctoMap (its 16-bit keys span +-range around the origin). */
void checkOctreeRange(const std::string& input, const obs::RawlogReader::Summary& in, double resolution)
{
	const double reach = in.maxReach + 2.0;  // plus a table's half-diagonal, generously
	const double far = std::max({-in.x0, in.x1, -in.y0, in.y1}) + reach;
	if (far >= render::OcTreeExport::range(resolution))
		throw core::Error(
			input + ": robot positions reach " + std::to_string(far - reach) + " m from the origin, beyond the map.bt export's range of +-" +
			std::to_string(render::OcTreeExport::range(resolution)) + " m at octomap_resolution " + std::to_string(resolution) +
			" m (raise it in the map config)");
}

int run(Options& o)
{
	// Everything that can be wrong with the inputs is checked before any output is made.
	if (o.config.empty()) o.config = core::ConfigPaths::find("whisker-map.ini");
	mrpt::maps::CMultiMetricMap multimap(maps::MapConfig::load(o.config));
	auto map = multimap.mapByClass<maps::CHierarchicalObjectMap>();
	if (!map) throw core::Error(o.config + ": no hierarchicalObjectMap was created (is libwhiskermap-maps loaded?)");
	if (o.seed) map->insertionOptions.seed = *o.seed;
	using TMode = maps::CHierarchicalObjectMap::TInsertionOptions::TMode;
	if (!o.mode.empty()) map->insertionOptions.mode = o.mode == "lasting" ? TMode::Lasting : TMode::PerPose;
	if (o.snapshotPose >= 0 && map->lasting())
		throw core::Error("--snapshot-pose draws a per-pose blackboard: it needs --mode per_pose");
	map->insertionOptions.keep_history = false;  // the outputs stream instead
	if (o.snapshotTemperature >= static_cast<int>(map->samplerParams.schedule.size()))
		throw core::Error("--snapshot-temperature " + std::to_string(o.snapshotTemperature) + ": the schedule has only " +
						  std::to_string(map->samplerParams.schedule.size()) + " temperatures");
	std::optional<world::World> world;
	if (!o.world.empty()) world = world::World::load(o.world);
	MapOutputs::TSettings settings;
	settings.input = o.input, settings.config = o.config, settings.world = world ? &*world : nullptr;
	settings.snapshotPose = o.snapshotPose, settings.snapshotTemperature = o.snapshotTemperature;
	settings.quiet = o.quiet, settings.simpleMap = o.simpleMap, settings.jobs = o.jobs;
	OutputDir out(o.outdir);  // refuses -o "" or a file
	obs::RawlogReader reader(o.input);  // checks the whole rawlog before any work
	const auto& summary = reader.summary();
	checkOctreeRange(o.input, summary, map->renderOptions.octomap_resolution);
	MapOutputs::pictureBounds(summary, settings.world, settings);
	settings.sweeps = summary.sweepCount;
	settings.maxSigmaR = summary.maxSigmaR;
	if (summary.sweepCount == 0)
		throw core::Error(o.input + ": holds no whisker observations (CObservationWhiskerContacts)");
	if (o.snapshotPose >= static_cast<int>(summary.sweepCount))
		throw core::Error("--snapshot-pose " + std::to_string(o.snapshotPose) + ": the rawlog has only " +
						  std::to_string(summary.sweepCount) + " sweeps");

	const auto t0 = std::chrono::steady_clock::now();
	MapOutputs outputs(out, *map, settings);
	const bool bar = !o.quiet && ::isatty(STDERR_FILENO);
	MapRunner runner(multimap, *map, o.jobs, [&](size_t i, const obs::RawlogReader::Sweep& sw, double ms) {
		outputs.onStep(i, sw, ms);
		if (bar && i % 100 == 0) std::fprintf(stderr, "\rwhisker-map: %zu sweeps", i + 1);
	});
	if (o.snapshotPose >= 0) runner.snapshot(static_cast<size_t>(o.snapshotPose), o.snapshotTemperature);
	obs::RawlogReader::Sweep sweep;
	if (o.reverse)
	{
		// The sweeps last to first: the whole log in memory (--reverse is a test of order).
		std::vector<obs::RawlogReader::Sweep> all;
		while (reader.next(sweep)) all.push_back(sweep);
		for (auto it = all.rbegin(); it != all.rend(); ++it) runner.add(*it);
	}
	else
		while (reader.next(sweep)) runner.add(sweep);
	runner.flush();
	map->annealPending();  // the last sweeps of a batch (insertOpts batch_sweeps > 1)
	const auto& contents = summary;
	if (bar) std::fprintf(stderr, "\rwhisker-map: %zu sweeps\n", contents.sweepCount);
	const std::string text = outputs.finish(
		std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
	out.commit();
	if (!o.quiet)
		std::printf("%swhisker-map: %zu sweeps -> %s (%s); median %.3f ms per sweep\n", text.c_str(),
					contents.sweepCount, o.outdir.c_str(), map->asString().c_str(), outputs.medianMs());
	return 0;
}
}  // namespace

int WhiskerMapApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-map: map tables from whisker contacts. Runs a CHierarchicalObjectMap (Fox & "
		"Prescott's hierarchical model and annealed blackboard sampler) over every whisker sweep "
		"of a rawlog (either MRPT layout) and writes, in OUTDIR: map_tables.csv (the map), "
		"map_candidates.csv, map.png, map.3Dscene, map.bt (OctoMap), summary.json, with the model key "
		"walls map_walls.csv, with --world "
		"metrics.json, and in the per-pose mode per_pose_tables.csv and montage.png (doc/outputs.md)."};
	Options o;
	app.add_option("-i,--input", o.input, "Input rawlog with CObservationWhiskerContacts sweeps")->required();
	app.add_option("-c,--config", o.config, "CMultiMetricMap .ini (default: the shipped config/whisker-map.ini)");
	app.add_option("-o,--out", o.outdir, "Output folder (created; files in it are replaced only when the run succeeds)")->required();
	app.add_option("--mode", o.mode,
				   "lasting: one map fusing every contact (default of the shipped config); per_pose: the "
				   "paper's independent steps on the 7 latest contacts, merged by votes (overrides insertOpts mode)")
		->check(CLI::IsMember({"lasting", "per_pose"}));
	app.add_flag("--reverse", o.reverse,
				 "Insert the sweeps last to first (reads the whole rawlog into memory): how much the map "
				 "depends on the order of the evidence");
	app.add_option("--seed", o.seed, "Override the map's base seed (insertOpts seed); same seed, same maps");
	app.add_option("--world", o.world,
				   "Ground-truth world .ini: drawn in the pictures, and the maps are evaluated against it "
				   "(metrics.json, and \"metrics\" in summary.json; doc/evaluation.md)");
	app.add_option("--snapshot-pose", o.snapshotPose,
				   "Also draw the blackboard of this sweep (0-based) at a hot temperature and its MAP "
				   "(the paper's figs. 1-2)");
	app.add_option("--snapshot-temperature", o.snapshotTemperature,
				   "Schedule index (0 = hottest) of the --snapshot-pose blackboard picture")
		->check(CLI::NonNegativeNumber)
		->capture_default_str();
	app.add_option("-j,--jobs", o.jobs,
				   "Per-pose mode: threads solving sampler steps; outputs are identical for any value (the "
				   "lasting mode inserts in order on one thread)")
		->check(CLI::Range(1u, 256u))
		->capture_default_str();
	app.add_flag("--simplemap", o.simpleMap,
				 "Also write map.simplemap (the sweeps with their poses, for MRPT apps that rebuild the map; "
				 "streamed)");
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-map", [&] { return run(o); });
}
}  // namespace whiskermap::cli
