#include <CLI/CLI.hpp>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/OutputTransaction.h>
#include <whiskermap/render/TopDownImage.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/RawlogWriter.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/cli/WhiskerSimApp.h>
#include <whiskermap/cli/RawlogFormatOption.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace whiskermap::cli
{
using namespace whiskermap::world;
namespace
{
struct Options
{
	std::string world, trajectory = "paper-grid", path, robot = "scratchbot", noise = "default";
	std::string format = "obs", out, png;
	int grid = 10, repeat = 1;
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

int run(const Options& o)
{
	const World w = World::load(o.world).tiled(o.tiles[0], o.tiles[1]);
	const Robot robot = Robot::load(core::ConfigPaths::resolve(o.robot, "robots"));
	const auto noise = NoisePreset::load(o.noise);
	// Poses one at a time (bounded memory however long the trajectory); a path file is
	// checked whole before anything is simulated.
	const auto poses = o.path.empty() ? Trajectory::paperGridSource(w, o.grid * o.tiles[0], o.grid * o.tiles[1])
									  : Trajectory::pathFileSource(o.path);
	WhiskerSimulator sim(w, robot, noise, o.seed);

	// Every output (rawlog, its ground truth, the picture) is staged and committed together.
	core::OutputTransaction outputs;
	const std::filesystem::path op(o.out);
	const std::string worldPath = (op.parent_path() / (op.stem().string() + "_ground_truth_world.ini")).string();
	const std::string pngPath = o.png.empty() ? "" : outputs.stage(o.png);
	const std::string stagedRawlog = outputs.stage(o.out);
	outputs.stage(RawlogWriter::groundTruthPathFile(o.out));  // RawlogWriter writes it beside the staged rawlog
	const std::string stagedWorld = outputs.stage(worldPath);

	// Fixed, synthetic clock: one sweep per second from a fixed epoch (reproducible bytes).
	const double t0 = 1300000000.0;
	RawlogWriter out(stagedRawlog, RawlogFormatOption::parse(o.format));
	render::TopDownImage picture(w.x_min, w.x_max, w.y_min, w.y_max);
	ContactStatistic stat;
	size_t written = 0, skipped = 0, contacts = 0, wallContacts = 0;
	std::vector<WhiskerSimulator::Truth> truth;
	mrpt::poses::CPose2D p;
	for (int k = 0; k < o.repeat; k++)
		for (poses->rewind(); poses->next(p);)
		{
			if (!sim.poseIsFree(p))
			{
				skipped++;
				if (!o.quiet)
					std::cerr << "whisker-sim: skipping pose (" << p.x() << ", " << p.y()
							  << "): the robot body would overlap a leg or wall\n";
				continue;
			}
			const auto sweep = sim.sense(p, mrpt::Clock::fromDouble(t0 + written), &truth);
			out.write(p, *sweep);
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
				for (const auto& s : sweep->toShapelets(p)) picture.shapelet(s, {220, 30, 30});
			}
			stat.add(onTables);
		}
	if (written == 0) throw core::Error(o.out + ": every pose was blocked, nothing to write");
	out.close();
	w.save(stagedWorld);
	if (!o.png.empty())
	{
		picture.arena(w, {0, 0, 0});
		for (const auto& t : w.tables) picture.table(t, {0, 0, 200}, 2);
		picture.caption(std::filesystem::path(o.out).filename().string() + ": tables (blue), robot poses (grey), contacts + normals (red)");
		picture.save(pngPath);
	}
	outputs.commit();

	if (!o.quiet)
	{
		std::printf("whisker-sim: wrote %s (%zu sweeps, %zu poses skipped)\n", o.out.c_str(), written, skipped);
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
		"sweeps as an MRPT rawlog (CObservationWhiskerContacts), with ground truth beside it "
		"(OUT_ground_truth_robot_path.txt, OUT_ground_truth_world.ini)."};
	Options o;
	app.add_option("-w,--world", o.world, "World .ini (arena and tables; see doc/formats.md)")
		->required();
	app.add_option(
		   "--trajectory", o.trajectory,
		   "paper-grid: N x N positions x 4 compass headings over the arena")
		->check(CLI::IsMember({"paper-grid"}))
		->capture_default_str();
	app.add_option("--grid", o.grid, "N for paper-grid: N x N positions per tile (default 10: 400 poses per tile)")
		->check(CLI::Range(1, 1000))
		->capture_default_str();
	app.add_option("--tiles", o.tiles, "NX NY: repeat the world NX x NY times (same density; for scaling runs)")
		->expected(2)
		->check(CLI::Range(1, 100))
		->capture_default_str();
	app.add_option("--repeat", o.repeat, "Run the trajectory this many times (new noise each time)")
		->check(CLI::Range(1, 100000))
		->capture_default_str();
	app.add_option("--path", o.path, "Pose file, one 'x y yaw_deg' per line (replaces --trajectory)")
		->check(CLI::ExistingFile);
	app.add_option("--robot", o.robot, "Robot geometry: a preset in config/robots/ or a .ini file")
		->capture_default_str();
	app.add_option(
		   "--noise", o.noise,
		   "Sensor noise: noiseless, default, very-noisy (config/noise/) or a .ini")
		->capture_default_str();
	app.add_option("--seed", o.seed, "Random seed; the same seed gives the same bytes")
		->capture_default_str();
	RawlogFormatOption::add(app, o.format);
	app.add_option("-o,--out", o.out, "Output rawlog path")->required();
	app.add_option("--png", o.png, "Also draw the world, poses and contacts into this PNG");
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-sim", [&] { return run(o); });
}
}  // namespace whiskermap::cli
