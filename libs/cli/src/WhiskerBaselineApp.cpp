#include <CLI/CLI.hpp>
#include <whiskermap/baseline/BatchFit.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/cli/WhiskerBaselineApp.h>
#include <whiskermap/maps/MapCsv.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>

#include <cstdio>
#include <iostream>

namespace whiskermap::cli
{
namespace
{
struct Options
{
	std::string input, out, config;
	double length = 0, width = 0, legWidth = 0, texture = -1;
	bool quiet = false;
};

/** Opens `path` for writing; the caller fcloses it through `close`. */
FILE* create(const std::string& path)
{
	FILE* f = std::fopen(path.c_str(), "w");
	if (!f) throw core::Error(path + ": cannot create file");
	return f;
}

void close(FILE* f, const std::string& path)
{
	const bool ok = std::ferror(f) == 0;
	if (std::fclose(f) != 0 || !ok) throw core::Error(path + ": write failed");
}

void writeTables(const std::string& path, const baseline::BatchFit& fit, const baseline::TBaselineParams& p)
{
	// whisker-map's map format (doc/outputs.md): every table the fit keeps is certain to it.
	std::vector<maps::TMappedObject> objects;
	for (const auto& t : fit.tables)
		objects.push_back(
			{world::Table{t.centre.x(), t.centre.y(), core::wrapToPi(t.yaw), p.table_length, p.table_width, p.leg_width, t.texture},
			 1.0, t.contacts, static_cast<uint32_t>(t.legCount())});
	maps::MapCsv::writeObjects(path, objects);
}

void writeLegs(const std::string& path, const baseline::BatchFit& fit)
{
	std::vector<int> tableOf(fit.legs.legs.size(), -1), cornerOf(fit.legs.legs.size(), -1);
	for (size_t i = 0; i < fit.tables.size(); i++)
		for (int k = 0; k < 4; k++)
			if (fit.tables[i].legs[k] >= 0) tableOf[fit.tables[i].legs[k]] = int(i), cornerOf[fit.tables[i].legs[k]] = k;
	FILE* f = create(path);
	std::fprintf(f, "id,x,y,yaw_deg,yaw_sigma_deg,contacts,faces,outliers,texture,table,corner\n");
	for (size_t j = 0; j < fit.legs.legs.size(); j++)
	{
		const auto& l = fit.legs.legs[j];
		std::fprintf(
			f, "%zu,%.6f,%.6f,%.4f,%.4f,%zu,%d,%zu,%.4f,%d,%d\n", j, l.centre.x(), l.centre.y(), core::rad2deg(l.yaw),
			core::rad2deg(l.yawSigma), l.members.size(), l.faces, l.outliers, l.texture, tableOf[j], cornerOf[j]);
	}
	close(f, path);
}

int run(const Options& o)
{
	auto p = o.config.empty() ? baseline::TBaselineParams{} : baseline::TBaselineParams::fromConfig(o.config);
	if (o.length > 0) p.table_length = o.length;
	if (o.width > 0) p.table_width = o.width;
	if (o.legWidth > 0) p.leg_width = o.legWidth;
	if (o.texture >= 0) p.texture = o.texture;
	if (p.leg_width >= std::min(p.table_length, p.table_width))
		throw core::Error("--leg-width must be smaller than the table length and width");

	obs::RawlogReader reader(o.input);  // streamed: memory bounded by BatchInput's samples
	baseline::BatchInput input(p);
	obs::RawlogReader::Sweep sweep;
	while (reader.next(sweep)) input.add(sweep);
	if (input.sweeps() == 0) throw core::Error(o.input + ": holds no whisker sweeps");
	const auto fit = baseline::BatchFit::run(input, p);

	OutputDir dir(o.out);
	writeTables(dir.path("map_tables.csv"), fit, p);
	writeLegs(dir.path("baseline_legs.csv"), fit);
	dir.commit();
	if (!o.quiet)
	{
		const auto& L = fit.legs;
		std::printf(
			"whisker-baseline: %llu sweeps, %llu contacts (%zu kept, %zu past the texture gate); %zu legs, %zu "
			"clusters rejected (%zu contacts), %zu split; %zu table proposals (%zu contradicted by free space); "
			"%zu tables -> %s\n",
			static_cast<unsigned long long>(input.sweeps()), static_cast<unsigned long long>(input.contactsSeen()),
			fit.contacts.size(), L.contactsUsed, L.legs.size(), L.clustersRejected, L.contactsRejected,
			L.splits, fit.proposals, fit.contradicted, fit.tables.size(), dir.finalPath("map_tables.csv").c_str());
	}
	return 0;
}
}  // namespace

int WhiskerBaselineApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-baseline: the plain batch geometric fit over all contacts of a run (issue 7's "
		"baseline, doc/baseline.md): cluster contacts into legs, fit a square leg to each, match "
		"leg spacings to the known table, fit each table to its contacts. Writes "
		"OUTDIR/map_tables.csv (whisker-map's columns: whisker-eval scores it) and "
		"OUTDIR/baseline_legs.csv."};
	Options o;
	app.add_option("-i,--input", o.input, "Input rawlog (whisker sweeps, either rawlog layout)")->required();
	app.add_option("-o,--out", o.out, "Output folder (created if needed)")->required();
	app.add_option(
		"-c,--config", o.config,
		"whisker-map .ini whose [MetricMap_hierarchicalObjectMap_00_model] section gives the known "
		"table (table_length, table_width, leg_width, texture); default: built-in values (1.0, 0.6, 0.05, 0.7)");
	app.add_option("--table-length", o.length, "Override: leg-centre spacing along the table (m)")
		->check(CLI::Range(1e-3, 100.0));
	app.add_option("--table-width", o.width, "Override: leg-centre spacing across the table (m)")
		->check(CLI::Range(1e-3, 100.0));
	app.add_option("--leg-width", o.legWidth, "Override: side of a square leg (m)")->check(CLI::Range(1e-4, 10.0));
	app.add_option("--texture", o.texture, "Override: texture of table legs, in [0, 1]")->check(CLI::Range(0.0, 1.0));
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-baseline", [&] { return run(o); });
}
}  // namespace whiskermap::cli
