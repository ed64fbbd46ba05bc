#include <unistd.h>

#include <CLI/CLI.hpp>
#include <whiskermap/cli/MapOutputs.h>
#include <whiskermap/cli/MapRunner.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/cli/PoseSpool.h>
#include <whiskermap/cli/SlamOutputs.h>
#include <whiskermap/cli/SlamSmoothing.h>
#include <whiskermap/cli/WhiskerSlamApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/heapInUseMb.h>
#include <whiskermap/core/peakRssMb.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/slam/RbpfSlam.h>
#include <whiskermap/world/PathLog.h>

#include <algorithm>
#include <chrono>
#include <tuple>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>

namespace whiskermap::cli
{
namespace
{
namespace fs = std::filesystem;
using Sweep = obs::RawlogReader::Sweep;

struct Options
{
	std::string input, config, outdir, truth, world;
	std::optional<unsigned> particles;
	std::optional<uint64_t> seed;
	size_t sweeps = 0;  ///< 0: all
	bool quiet = false;
	bool oracle = false;  ///< no filter: the true path smoothed against the true world's solids
};

/** The true path beside the rawlog, as whisker-sim writes it, if there is one. */
std::string truthBeside(const std::string& rawlog)
{
	const fs::path p(rawlog);
	const fs::path gt = p.parent_path() / (p.stem().string() + "_ground_truth_robot_path.txt");
	return fs::exists(gt) ? gt.string() : "";
}

/** Every particle's map: no history kept and no swept grid that nothing reads (the outputs
 *  come from a rebuild), and the sweeps annealed together, the Manhattan walls and the walls'
 *  extension that the SLAM config asks for; with `filter`, also its leg merge gap (the maps
 *  built after the filter keep the map config's own). */
void particleMaps(mrpt::maps::TSetOfMetricMapInitializers& inits, const slam::TSlamParams& params, bool filter)
{
	for (auto& def : inits)
		if (auto* ours = dynamic_cast<maps::CHierarchicalObjectMap::TMapDefinition*>(def.get()))
		{
			ours->insertionOptions.keep_history = false;
			if (filter && params.leg_merge_gap > 0) ours->insertionOptions.lasting.leg_merge_gap = params.leg_merge_gap;
			if (!ours->sweptGridRead()) ours->insertionOptions.record_swept = false;
			if (params.batch_sweeps > 0) ours->insertionOptions.lasting.batch_sweeps = params.batch_sweeps;
			if (params.wall_extension > 0) ours->likelihoodOptions.wall_extension = params.wall_extension;
			if (!params.manhattan_walls) continue;
			ours->modelParams.walls = ours->modelParams.manhattan_walls = true;
			ours->modelParams.wall_axis = params.wall_axis;
		}
}

/** The same tables, in any order (table ids, hence the order, may differ: the particle's map
 *  also answered likelihood queries). */
bool sameTables(std::vector<world::Table> a, std::vector<world::Table> b)
{
	if (a.size() != b.size()) return false;
	const auto byPose = [](const world::Table& p, const world::Table& q) {
		return std::tie(p.x, p.y, p.yaw) < std::tie(q.x, q.y, q.yaw);
	};
	std::sort(a.begin(), a.end(), byPose);
	std::sort(b.begin(), b.end(), byPose);
	for (size_t i = 0; i < a.size(); i++)
		if (a[i].x != b[i].x || a[i].y != b[i].y || a[i].yaw != b[i].yaw) return false;
	return true;
}

/** What the filter and the oracle write as they read the sweeps. */
struct Streams
{
	world::PathLog::Writer& odometry;
	PoseSpool& start;  ///< the path the smoother starts from: the best particle's, or the truth
};

/** Runs the particle filter over the first `n` sweeps; the best particle's path goes to
 *  `io.start` as its poses settle, the filter's figures to `result`. */
std::unique_ptr<slam::RbpfSlam> runFilter(
	const Options& o, size_t n, const slam::TSlamParams& params, const mrpt::maps::TSetOfMetricMapInitializers& inits,
	Streams io, SlamOutputs::TRun& result)
{
	auto slam = std::make_unique<slam::RbpfSlam>(params, inits);
	result.particles = slam->particles().particlesCount();
	if (!o.quiet && result.particles < params.particles)
		std::fprintf(stderr, "whisker-slam: odometry told exact: 1 particle (the %u asked for would each follow the "
					 "same path and build the same map)\n", params.particles);
	std::deque<double> times;  // timestamps of the sweeps whose poses have not settled
	const auto settled = [&](const mrpt::poses::CPose2D& p) {
		if (times.empty()) throw core::Error("whisker-slam: more poses settled than sweeps (a bug)");
		io.start.write(times.front(), p.asTPose());
		times.pop_front();
	};
	const bool bar = !o.quiet && ::isatty(STDERR_FILENO);
	size_t k = 0;
	obs::RawlogReader::forEach(o.input, [&](const Sweep& sw) {
		if (k >= n) return;
		const double t = mrpt::Clock::toDouble(sw.obs->timestamp);
		io.odometry.write(t, sw.robotPose);
		times.push_back(t);
		const auto& step = slam->step(sw);
		slam->settle(settled);
		result.steps.add(step.ms, step.ess, step.resampled, slam->paths().nodes());
		k++;
		if (k == std::max<size_t>(n / 10, 1))
			result.filterRssTenthMb = core::peakRssMb(), result.filterHeapTenthMb = core::heapInUseMb(),
			result.filterMapsTenth = slam->mapTotals();
		if (bar && (k % 10 == 0 || k == n))
			std::fprintf(stderr, "\rwhisker-slam: %zu/%zu sweeps, %zu particles, ESS %.2f", k, n, result.particles,
						 step.ess);
	});
	if (bar) std::fprintf(stderr, "\n");
	result.filterRssMb = core::peakRssMb();
	result.filterHeapMb = core::heapInUseMb();
	result.filterMaps = slam->mapTotals();
	for (const auto& p : slam->bestPath()) settled(p);
	return slam;
}

/** --oracle: no filter; the true path (`truth`, checked to hold `n` poses) goes to `io.start`. */
void oracleStart(const Options& o, size_t n, const std::string& truth, Streams io)
{
	world::PathLog::Reader r(truth);
	world::PathLog::Entry e;
	obs::RawlogReader::forEach(o.input, [&](const Sweep& sw) {
		if (r.count() >= n || !r.next(e)) return;
		const double t = mrpt::Clock::toDouble(sw.obs->timestamp);
		io.odometry.write(t, sw.robotPose);
		io.start.write(t, e.pose);
	});
}

int run(Options& o)
{
	// Everything that can be wrong with the inputs is checked before any output is made.
	if (o.config.empty()) o.config = core::ConfigPaths::find("whisker-slam.ini");
	auto params = slam::TSlamParams::load(o.config);
	const auto smoothing = smooth::TSmoothParams::load(o.config);
	if (o.particles && *o.particles == 0) throw core::Error("--particles 0: the filter needs at least one particle");
	if (o.particles) params.particles = *o.particles;
	if (o.seed) params.seed = *o.seed;
	auto inits = maps::MapConfig::load(params.map_config);
	particleMaps(inits, params, true);
	// The maps built at a path after the filter (the smoother's, the one written): without
	// the particles' leg merge gap, so legs mapped twice stay apart for the smoother (eq. S4).
	auto built = maps::MapConfig::load(params.map_config);
	particleMaps(built, params, false);
	std::optional<world::World> world;
	if (!o.world.empty()) world = world::World::load(o.world);
	if (o.oracle && !world) throw core::Error("--oracle needs --world: the true solids to smooth against");
	SlamOutputs::TRun result;
	result.input = o.input, result.config = o.config, result.mapConfig = params.map_config, result.params = &params;
	result.truthPath = o.truth.empty() ? truthBeside(o.input) : o.truth;
	// Count the sweeps (this pass also verifies the whole rawlog) and check the true path.
	size_t all = 0;
	const auto contents = obs::RawlogReader::forEach(o.input, [&](const Sweep&) { all++; });
	if (contents.sweepCount == 0)
		throw core::Error(o.input + ": holds no whisker observations (CObservationWhiskerContacts)");
	const size_t n = o.sweeps ? std::min(o.sweeps, all) : all;
	result.sweeps = n;
	if (o.oracle && result.truthPath.empty())
		throw core::Error("--oracle needs the true path (--truth, or " + o.input + "'s _ground_truth_robot_path.txt)");
	if (!result.truthPath.empty())
	{
		const size_t poses = world::PathLog::count(result.truthPath, n);
		if (poses < n)
			throw core::Error(result.truthPath + ": " + std::to_string(poses) + " poses for " +
							  std::to_string(n) + " sweeps");
	}
	MapOutputs::TSettings settings;
	settings.input = o.input, settings.config = params.map_config, settings.world = world ? &*world : nullptr;
	settings.quiet = o.quiet, settings.summaryName = "map_summary.json";
	settings.sweeps = n, settings.maxSigmaR = contents.maxSigmaR;
	MapOutputs::pictureBounds(contents, settings.world, settings);

	// The filter (or, for --oracle, the truth). The paths go to disk as they settle: memory
	// holds the particles' maps and the poses not yet settled (doc/slam.md, "Memory").
	const auto t0 = std::chrono::steady_clock::now();
	OutputDir out(o.outdir);
	result.oracle = o.oracle;
	result.odometryFile = out.path(SlamOutputs::ODOMETRY), result.estimatedFile = out.path(SlamOutputs::ESTIMATED);
	world::PathLog::Writer odometry(result.odometryFile, SlamOutputs::ODOMETRY_TITLE);
	PoseSpool estimated;  // the path the smoother starts from, exact, for the map rebuilt at it
	std::unique_ptr<slam::RbpfSlam> slam;
	if (o.oracle)
		oracleStart(o, n, result.truthPath, {odometry, estimated});
	else
		slam = runFilter(o, n, params, inits, {odometry, estimated}, result);
	odometry.close();
	std::optional<smooth::PathSmoother::TResult> smoothed;
	if (smoothing.enabled || o.oracle)
	{
		const auto ts = std::chrono::steady_clock::now();
		std::vector<Eigen::Vector3d> path;
		estimated.rewind();
		double t;
		for (mrpt::math::TPose2D p; path.size() < n && estimated.next(t, p);) path.emplace_back(p.x, p.y, p.phi);
		// Particles that merge legs mapped twice leave their map no pairs to close loops on:
		// then the first pass smooths against a map built at the particle's path instead.
		const SlamSmoothing smoother(o.input, params);
		auto solids = o.oracle					  ? world->obstacles()
					  : params.leg_merge_gap > 0 ? smoother.solidsAt(path, built)
												 : slam->bestMap().mappedSolids();
		auto passes = smoothing;
		if (o.oracle) passes.passes = 1;  // a further pass would smooth against our own map
		smoothed = smoother.run(std::move(path), std::move(solids), passes, built);
		result.smoothing = &*smoothed;
		result.smoothingSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count();
	}

	// The map, rebuilt by whisker-map's runner and writer at the estimated path's poses: the
	// smoothed path's, or without smoothing the best particle's (then the same insertions the
	// particle made, so the same map: checked below).
	mrpt::maps::CMultiMetricMap multimap(smoothed ? built : inits);
	auto map = multimap.mapByClass<maps::CHierarchicalObjectMap>();
	MapOutputs outputs(out, *map, settings);
	MapRunner runner(multimap, *map, 1, [&](size_t i, const Sweep& sw, double ms) { outputs.onStep(i, sw, ms); });
	world::PathLog::Writer estimatedText(result.estimatedFile, SlamOutputs::ESTIMATED_TITLE);
	std::optional<world::PathLog::Writer> filterText;
	if (slam)
	{
		result.filterFile = out.path(SlamOutputs::FILTER);
		filterText.emplace(result.filterFile, SlamOutputs::FILTER_TITLE);
	}
	estimated.rewind();
	size_t k = 0;
	obs::RawlogReader::forEach(o.input, [&](const Sweep& sw) {
		double t;
		mrpt::math::TPose2D pose;
		if (k >= n || !estimated.next(t, pose)) return;
		if (filterText) filterText->write(t, mrpt::poses::CPose2D(pose));
		const auto& s = smoothed ? smoothed->path[k] : Eigen::Vector3d(pose.x, pose.y, pose.phi);
		const mrpt::poses::CPose2D at(s[0], s[1], s[2]);
		estimatedText.write(t, at);
		runner.add({at, sw.obs});
		k++;
	});
	if (k < n) throw SlamSmoothing::shorter(o.input, k, n);
	runner.flush();
	estimatedText.close();
	if (filterText) filterText->close();
	if (!smoothed) result.mapMatches = sameTables(map->mapTables(), slam->bestMap().mapTables());
	if (params.disjoint_tables) map->likelihoodOptions.disjoint_tables = true;  // the map written only
	map->annealPending();  // the last sweeps of a batch (batch_sweeps): the particle's own map has them pending
	result.mapTables = map->mapTables();
	if (result.mapMatches == false && !o.quiet)
		std::fprintf(stderr, "whisker-slam: warning: the map written (rebuilt at the best path) differs from the best "
							 "particle's own map (summary.json: map_matches_best_particle; doc/slam.md)\n");
	result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	const std::string text = outputs.finish(result.wallSeconds);
	const std::string line = SlamOutputs::write(out, result, settings);
	out.commit();
	if (!o.quiet) std::printf("%swhisker-slam: %s -> %s\n", text.c_str(), line.c_str(), o.outdir.c_str());
	return 0;
}
}  // namespace

int WhiskerSlamApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-slam: tactile SLAM. Runs MRPT's Rao-Blackwellised particle filter "
		"(CMultiMetricMapPDF) on a rawlog (either layout), each particle holding a "
		"hierarchicalObjectMap; the particles move with the odometry's motion model and are "
		"weighed by the sweep likelihood; then the best particle's path is smoothed by least squares "
		"against its map ([smooth] in the config). Writes, in OUTDIR: estimated_path.txt (the smoothed "
		"path), filter_path.txt (the best particle's) and odometry_path.txt, one line per sweep in the "
		"ground-truth columns; the map built at the estimated path as whisker-map writes it (map_tables.csv, "
		"map_candidates.csv, map_walls.csv, "
		"map.png, map.3Dscene, map.bt, map_summary.json, with --world metrics.json); paths.png; "
		"summary.json (doc/slam.md)."};
	Options o;
	app.add_option("-i,--input", o.input, "Input rawlog with CObservationWhiskerContacts sweeps and odometry")->required();
	app.add_option("-o,--out", o.outdir, "Output folder (created; files in it are replaced only when the run succeeds)")
		->required();
	app.add_option("-c,--config", o.config,
				   "whisker-slam .ini: particles, seed, map config, motion model, resampling, smoothing "
				   "(default: the shipped config/whisker-slam.ini)");
	app.add_option("--particles", o.particles, "Particle count (overrides [slam] particles)");
	app.add_option("--seed", o.seed, "Seed of MRPT's random generator (overrides [slam] seed); same seed, same output");
	app.add_option("--truth", o.truth,
				   "True path file (timestamp x y yaw per sweep) for paths.png and the figures in summary.json "
				   "(default: <rawlog>_ground_truth_robot_path.txt beside the rawlog, if there)");
	app.add_option("--world", o.world, "Ground-truth world .ini: drawn in the pictures, the map scored against it");
	app.add_option("--sweeps", o.sweeps, "Use only the first N sweeps (0: all)")->capture_default_str();
	app.add_flag("--oracle", o.oracle,
				 "No filter: the true path smoothed (one pass) against the --world's legs and walls, the data "
				 "association and the solids' shapes known; the floor of this estimator on the log (doc/slam.md, "
				 "\"The floor\"). Writes no filter_path.txt");
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-slam", [&] { return run(o); });
}
}  // namespace whiskermap::cli
