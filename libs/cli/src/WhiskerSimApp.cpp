#include <CLI/CLI.hpp>
#include <whiskermap/cli/RawlogFormatOption.h>
#include <whiskermap/cli/SimTrajectory.h>
#include <whiskermap/cli/WhiskerSimApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/OutputTransaction.h>
#include <whiskermap/render/TopDownImage.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/OdometrySimulator.h>
#include <whiskermap/world/PathLog.h>
#include <whiskermap/world/RawlogWriter.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

namespace whiskermap::cli
{
using namespace whiskermap::world;
namespace
{
struct Options
{
	std::string world, robot = "scratchbot", noise = "default", odometry = "exact";
	std::string format = "obs", out, png;
	SimTrajectory trajectory;
	int repeat = 1;
	std::vector<int> tiles{1, 1};
	uint64_t seed = 1;
	bool quiet = false;
};

/** Mean and sample std-dev of whiskers touching tables, over sweeps touching >= 1 table. */
struct ContactStatistic
{
	double sum = 0, sumSq = 0;
	size_t n = 0;
	void add(int tableContacts)
	{
		if (tableContacts == 0) return;
		sum += tableContacts;
		sumSq += double(tableContacts) * tableContacts;
		n++;
	}
	double mean() const { return n ? sum / n : 0; }
	double stddev() const
	{
		return n > 1 ? std::sqrt(std::max(0.0, (sumSq - n * mean() * mean()) / (n - 1))) : 0;
	}
};

/** "<dir>/<stem><suffix>" beside the output rawlog. */
std::string beside(const std::string& rawlog, const std::string& suffix)
{
	const std::filesystem::path p(rawlog);
	return (p.parent_path() / (p.stem().string() + suffix)).string();
}

int run(const Options& o)
{
	const World w = World::load(o.world).tiled(o.tiles[0], o.tiles[1]);
	const Robot robot = Robot::load(core::ConfigPaths::resolve(o.robot, "robots"));
	const auto noise = NoisePreset::load(o.noise);
	const auto odometryNoise = OdometryNoise::load(o.odometry);
	WhiskerSimulator sim(w, robot, noise, o.seed);
	if (o.repeat > 1 && o.trajectory.path.empty() && o.trajectory.kind != "paper-grid")
		throw core::Error("--repeat applies to paper-grid and --path; use --duration or --length");
	// Poses one at a time (bounded memory however long the trajectory or --repeat).
	const auto planned = o.trajectory.poses(sim, o.tiles[0], o.tiles[1], o.seed);
	OdometrySimulator odometry(odometryNoise, o.seed);

	// Every output (rawlog, ground truth, odometry path, picture) is staged and committed together.
	core::OutputTransaction outputs;
	const std::string pngPath = o.png.empty() ? "" : outputs.stage(o.png);
	const std::string stagedRawlog = outputs.stage(o.out);
	outputs.stage(RawlogWriter::groundTruthPathFile(o.out));  // RawlogWriter writes it beside the staged rawlog
	const std::string stagedWorld = outputs.stage(beside(o.out, "_ground_truth_world.ini"));
	const std::string stagedOdometry = odometryNoise.exact() ? "" : outputs.stage(beside(o.out, "_odometry_path.txt"));

	// Fixed, synthetic clock: one sweep every 1/rate s from a fixed epoch (reproducible bytes).
	const double t0 = 1300000000.0;
	RawlogWriter out(stagedRawlog, RawlogFormatOption::parse(o.format));
	out.setMotionModel([&](const mrpt::poses::CPose2D& increment) { return odometryNoise.motionModel(increment); });
	std::optional<PathLog::Writer> odometryPath;
	if (!stagedOdometry.empty())
		odometryPath.emplace(
			stagedOdometry,
			"Odometry (dead-reckoning) robot path, as recorded in the rawlog, one line per whisker sweep");
	render::TopDownImage picture(w.x_min, w.x_max, w.y_min, w.y_max);
	ContactStatistic stat;
	size_t written = 0, skipped = 0, contacts = 0, wallContacts = 0;
	double travelled = 0;
	mrpt::poses::CPose2D p, previous, odo;
	std::vector<mrpt::poses::CPose2D> odometryPoses;  // for the picture
	std::vector<WhiskerSimulator::Truth> truth;
	for (int k = 0; k < o.repeat; k++)
		for (planned.source->rewind(); planned.source->next(p);)
		{
			if (planned.skipBlocked && !sim.poseIsFree(p))
			{
				skipped++;
				if (!o.quiet && k == 0)
					std::cerr << "whisker-sim: skipping grid pose (" << p.x() << ", " << p.y()
							  << "): the robot body would overlap a leg or wall\n";
				continue;
			}
			const auto sweep = sim.sense(p, mrpt::Clock::fromDouble(t0 + written / planned.rate), &truth);
			odo = odometry.next(p);
			out.write(odo, p, *sweep);
			if (odometryPath) odometryPath->write(mrpt::Clock::toDouble(sweep->timestamp), odo);
			if (written > 0) travelled += (p - previous).norm();
			previous = p;
			written++;
			int onTables = 0;
			for (const auto& t : truth)
			{
				onTables += t.table >= 0;
				wallContacts += t.wall;
			}
			contacts += sweep->contactCount();
			if (!o.png.empty())
			{
				picture.robot(p, {120, 120, 120});
				odometryPoses.push_back(odo);
				for (const auto& s : sweep->toShapelets(p)) picture.shapelet(s, {220, 30, 30});
			}
			stat.add(onTables);
		}
	if (written == 0) throw core::Error(o.out + ": every pose was blocked, nothing to write");
	out.close();
	if (odometryPath) odometryPath->close();
	w.save(stagedWorld);
	if (!o.png.empty())
	{
		picture.arena(w, {0, 0, 0});
		for (const auto& t : w.tables) picture.table(t, {0, 0, 200}, 2);
		picture.caption(std::filesystem::path(o.out).filename().string() + ": tables (blue), robot poses (grey), contacts + normals (red)");
		if (odometryPath)
		{
			picture.path(odometryPoses, {230, 140, 0}, 2);
			picture.caption("odometry path (orange)", {230, 140, 0});
		}
		picture.save(pngPath);
	}
	outputs.commit();

	if (!o.quiet)
	{
		std::printf("whisker-sim: wrote %s (%zu sweeps, %zu poses skipped)\n", o.out.c_str(), written, skipped);
		std::printf(
			"  trajectory: %.1f m travelled in %.3f s (%.6g sweeps per second)\n", travelled,
			(written - 1) / planned.rate, planned.rate);
		if (odometryPath)
			std::printf(
				"  odometry (%s): final error %.3f m, %.2f deg\n", o.odometry.c_str(),
				std::hypot(odo.x() - previous.x(), odo.y() - previous.y()),
				core::rad2deg(std::abs(core::wrapToPi(odo.phi() - previous.phi()))));
		std::printf("  contacts: %zu (%zu on walls)\n", contacts, wallContacts);
		std::printf(
			"  whiskers touching tables, over %zu sweeps with at least one: %.2f +/- %.2f "
			"(paper: 4.2 +/- 1.7)\n",
			stat.n, stat.mean(), stat.stddev());
	}
	return 0;
}
}  // namespace

int WhiskerSimApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-sim: simulate a whiskered robot in a world of tables and record its whisker "
		"sweeps as an MRPT rawlog (CObservationWhiskerContacts) with its odometry, the ground "
		"truth beside it (OUT_ground_truth_robot_path.txt, OUT_ground_truth_world.ini) and, "
		"with noisy odometry, the odometry path (OUT_odometry_path.txt)."};
	Options o;
	app.add_option("-w,--world", o.world, "World .ini (arena and tables; see doc/formats.md)")
		->required();
	o.trajectory.add(app);
	app.add_option("--tiles", o.tiles, "NX NY: repeat the world NX x NY times (same density; for scaling runs)")
		->expected(2)
		->check(CLI::Range(1, 100))
		->capture_default_str();
	app.add_option("--repeat", o.repeat, "Run the paper-grid or --path poses this many times (new noise each time)")
		->check(CLI::Range(1, 100000))
		->capture_default_str();
	app.add_option("--robot", o.robot, "Robot geometry: a preset in config/robots/ or a .ini file")
		->capture_default_str();
	app.add_option(
		   "--noise", o.noise,
		   "Sensor noise: noiseless, default, very-noisy (config/noise/) or a .ini")
		->capture_default_str();
	app.add_option(
		   "--odometry", o.odometry,
		   "Odometry noise: exact (odometry = truth), default (5% translation and 2 degrees of "
		   "heading error per metre, random walks, and a 1% scale bias), poor (twice that) "
		   "(config/odometry/) or a .ini; also sets the motion model of action-sf actions")
		->capture_default_str();
	app.add_option(
		   "--seed", o.seed,
		   "Random seed of the sensor noise, odometry noise and random trajectories (separate "
		   "streams); the same seed gives the same bytes")
		->capture_default_str();
	RawlogFormatOption::add(app, o.format);
	app.add_option("-o,--out", o.out, "Output rawlog path")->required();
	app.add_option("--png", o.png, "Also draw the world, poses and contacts into this PNG");
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-sim", [&] { return run(o); });
}
}  // namespace whiskermap::cli
