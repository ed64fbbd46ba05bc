#include <whiskermap/cli/RangeExport.h>
#include <whiskermap/cli/WhiskerExportApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/OutputTransaction.h>
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
	std::string in, out, ranges, rangesSimpleMap;
	bool quiet = false;
};

int run(const Options& o)
{
	if (o.out.empty() && o.ranges.empty() && o.rangesSimpleMap.empty())
		throw core::Error(o.in + ": nothing to write: give -o, --ranges or --ranges-simplemap");
	const obs::RawlogReader checked(o.in);  // the whole input checked before any output is written
	// Every output is staged and committed together (doc/outputs.md, "Outputs are all or nothing").
	core::OutputTransaction outputs;
	if (!o.out.empty())
	{
		world::ContactLogWriter out(outputs.stage(o.out), o.in);
		obs::RawlogReader::forEach(
			o.in, [&](const obs::RawlogReader::Sweep& s) { out.write(s.robotPose, *s.obs); });
		out.close();
		if (!o.quiet)
			std::printf(
				"whisker-export: wrote %s (%zu sweeps, %zu rows)\n", o.out.c_str(), out.sweeps(), out.rows());
	}
	if (!o.ranges.empty())
	{
		const size_t n = RangeExport::writeRawlog(o.in, outputs.stage(o.ranges));
		if (!o.quiet) std::printf("whisker-export: wrote %s (%zu sweeps as range rays)\n", o.ranges.c_str(), n);
	}
	if (!o.rangesSimpleMap.empty())
	{
		const size_t n = RangeExport::writeSimpleMap(o.in, outputs.stage(o.rangesSimpleMap));
		if (!o.quiet)
			std::printf("whisker-export: wrote %s (%zu sweeps as range rays at their poses)\n", o.rangesSimpleMap.c_str(), n);
	}
	outputs.commit();
	return 0;
}
}  // namespace

int WhiskerExportApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-export: write the whisker sweeps of a rawlog (either layout: odometry + "
		"observations, or actions + sensory frames) as a text contact log (CSV, '# whiskermap "
		"contacts v1', one row per whisker per sweep; doc/formats.md), and/or as stock MRPT "
		"range rays for an occupancy grid (each whisker one CObservationRange from its base "
		"along its shaft: the contact distance, or the whisker length when it touched nothing). "
		"Numbers carry enough digits that whisker-import gives back the same sweeps bit for "
		"bit; the sensor's noise and whisker mountings are listed in comment lines."};
	Options o;
	app.add_option("-i,--input", o.in, "Rawlog to read")->required();
	app.add_option("-o,--out", o.out, "Contact log to write (.csv)");
	app.add_option("--ranges", o.ranges,
		"Rawlog to write with every sweep replaced by its range rays, same layout, odometry and "
		"actions kept (stock pf-localization / rbpf-slam with an occupancy grid: config/grid-*.ini)");
	app.add_option("--ranges-simplemap", o.rangesSimpleMap,
		"MRPT .simplemap to write: each sweep's range rays at the rawlog's robot pose (from a "
		"rawlog with exact odometry: the true poses), the map file of config/grid-pf-localization.ini");
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-export", [&] { return run(o); });
}
}  // namespace whiskermap::cli
