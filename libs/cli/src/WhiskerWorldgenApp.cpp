#include <CLI/CLI.hpp>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/cli/WhiskerWorldgenApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WorldGenerator.h>

#include <filesystem>
#include <iostream>

namespace whiskermap::cli
{
namespace
{
struct Options
{
	std::string category, out, robot = "scratchbot";
	std::vector<std::string> noises{"noiseless", "default", "very-noisy"};
	uint64_t seed = 1;
	int64_t simSeed = -1;
	size_t window = 7;
	bool quiet = false;
};

int run(const Options& o)
{
	world::WorldGenerator::TSettings s;
	s.robot = world::Robot::load(core::ConfigPaths::resolve(o.robot, "robots"));
	s.noises.clear();
	for (const auto& n : o.noises) s.noises.push_back(world::NoisePreset::load(n));
	s.simSeed = o.simSeed < 0 ? o.seed : uint64_t(o.simSeed);
	s.window = o.window;
	const auto scenario = world::WorldGenerator(s).generate(o.category, o.seed);

	const std::filesystem::path prefix(o.out);
	const std::string stem = prefix.filename().string();
	OutputDir dir(prefix.has_parent_path() ? prefix.parent_path().string() : ".");
	const std::string text = scenario.description();
	scenario.world.save(dir.path(stem + ".ini"), text);
	world::Trajectory::writePathFile(dir.path(stem + ".path"), scenario.path, text + "one pose per line: x y yaw_deg");
	dir.commit();
	if (!o.quiet) std::cout << "whisker-worldgen: wrote " << o.out << ".ini and " << o.out << ".path\n" << text;
	return 0;
}
}  // namespace

int WhiskerWorldgenApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-worldgen: generate an evaluation world of tables and the robot path that "
		"explores it (doc/eval-worlds.md), written as PREFIX.ini (world, doc/formats.md) and "
		"PREFIX.path (whisker-sim --path). The same category and seed give the same bytes."};
	Options o;
	std::string categories;
	for (const auto& c : world::WorldGenerator::categories()) categories += (categories.empty() ? "" : ", ") + c;
	app.add_option("--category", o.category, "World category: " + categories)
		->required()
		->check(CLI::IsMember(world::WorldGenerator::categories()));
	app.add_option("--seed", o.seed, "Layout seed")->capture_default_str();
	app.add_option("-o,--out", o.out, "Output prefix: writes PREFIX.ini and PREFIX.path")->required();
	app.add_option("--robot", o.robot, "Robot geometry: a preset in config/robots/ or a .ini file")
		->capture_default_str();
	app.add_option(
		   "--noise", o.noises,
		   "Noise levels at which the path is checked with the simulator (presets or .ini files)")
		->capture_default_str();
	app.add_option("--sim-seed", o.simSeed, "whisker-sim --seed used for the checks (default: --seed)");
	app.add_option(
		   "--window", o.window,
		   "The map's working memory in contacts: a sparse path never holds two legs of one "
		   "table within this many consecutive contacts")
		->check(CLI::Range(size_t(1), size_t(1000)))
		->capture_default_str();
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-worldgen", [&] { return run(o); });
}
}  // namespace whiskermap::cli
