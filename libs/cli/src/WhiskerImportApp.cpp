#include <whiskermap/cli/WhiskerImportApp.h>
#include <whiskermap/cli/RawlogFormatOption.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/world/ContactLogReader.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/RawlogWriter.h>

#include <CLI/CLI.hpp>
#include <cstdio>

namespace whiskermap::cli
{
using namespace whiskermap::world;
namespace
{
struct Options
{
	std::string in, robot, noise = "default", format = "obs", out;
	bool quiet = false;
};

int run(const Options& o)
{
	const Robot robot = Robot::load(core::ConfigPaths::resolve(o.robot, "robots"));
	const auto noise = NoisePreset::load(o.noise);
	ContactLogReader in(o.in, robot, noise);
	RawlogWriter out(o.out, RawlogFormatOption::parse(o.format), RawlogWriter::GroundTruth::None);
	ContactLogReader::Sweep s;
	size_t contacts = 0;
	while (in.next(s))
	{
		out.write(s.odometry, *s.obs);
		contacts += s.obs->contactCount();
	}
	out.close();  // only now does the rawlog appear: the whole log was valid
	if (!o.quiet)
		std::printf(
			"whisker-import: wrote %s (%zu sweeps of %zu whiskers from %zu rows, %zu contacts)\n",
			o.out.c_str(), in.sweeps(), robot.whiskers.size(), in.rows(), contacts);
	return 0;
}
}  // namespace

int WhiskerImportApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-import: read a text contact log (CSV, '# whiskermap contacts v1', one row per "
		"whisker per sweep; doc/formats.md) and write its sweeps as an MRPT rawlog of "
		"CObservationWhiskerContacts, for whisker-map, rbpf-slam and the other tools. The whole "
		"log is checked; on the first bad value it stops with one line naming the file, line "
		"and column, and writes nothing."};
	Options o;
	app.add_option("-i,--input", o.in, "Contact log to read (.csv)")->required();
	app.add_option(
		   "--robot", o.robot,
		   "Robot geometry (whisker mountings, lengths, sweeps): a preset in config/robots/ "
		   "(e.g. scratchbot) or a robot .ini; the log's whisker column indexes its whiskers")
		->required();
	app.add_option(
		   "--noise", o.noise,
		   "Sensor noise to record in each sweep (the mapper's reading noise): noiseless, "
		   "default, very-noisy (config/noise/) or a noise .ini")
		->capture_default_str();
	RawlogFormatOption::add(app, o.format);
	app.add_option("-o,--out", o.out, "Output rawlog path")->required();
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-import", [&] { return run(o); });
}
}  // namespace whiskermap::cli
