#include <whiskermap/cli/WhiskerExportApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/ContactLogWriter.h>

#include <CLI/CLI.hpp>
#include <cstdio>

namespace whiskermap::cli
{
namespace
{
struct Options
{
	std::string in, out;
	bool quiet = false;
};

int run(const Options& o)
{
	world::ContactLogWriter out(o.out, o.in);
	obs::RawlogReader::forEach(
		o.in, [&](const obs::RawlogReader::Sweep& s) { out.write(s.robotPose, *s.obs); });
	out.close();
	if (!o.quiet)
		std::printf(
			"whisker-export: wrote %s (%zu sweeps, %zu rows)\n", o.out.c_str(), out.sweeps(),
			out.rows());
	return 0;
}
}  // namespace

int WhiskerExportApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-export: write the whisker sweeps of a rawlog (either layout: odometry + "
		"observations, or actions + sensory frames) as a text contact log (CSV, '# whiskermap "
		"contacts v1', one row per whisker per sweep; doc/formats.md). Numbers carry enough "
		"digits that whisker-import gives back the same sweeps bit for bit; the sensor's "
		"noise and whisker mountings are listed in comment lines."};
	Options o;
	app.add_option("-i,--input", o.in, "Rawlog to read")->required();
	app.add_option("-o,--out", o.out, "Contact log to write (.csv)")->required();
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-export", [&] { return run(o); });
}
}  // namespace whiskermap::cli
