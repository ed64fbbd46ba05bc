#include <gtest/gtest.h>
#include <whiskermap/baseline/BatchFit.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/world/World.h>

#include <filesystem>
#include <fstream>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

/** The fit of a shipped dataset, its sweeps fed `passes` times (a log driving the same path
 *  again and again), with `p` from the shipped configuration changed by `change`. */
template <class Change>
std::pair<eval::MapEvaluation, baseline::BatchFit> fitDataset(const std::string& preset, int passes, Change change)
{
	auto p = baseline::TBaselineParams::fromConfig(SRC + "/config/whisker-map.ini");
	change(p);
	baseline::BatchInput input(p);
	const auto sweeps = obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog").sweeps;
	for (int k = 0; k < passes; k++)
		for (const auto& s : sweeps) input.add(s);
	auto fit = baseline::BatchFit::run(input, p);
	std::vector<world::Table> tables;
	for (const auto& t : fit.tables)
	{
		world::Table w;
		w.x = t.centre.x(), w.y = t.centre.y(), w.yaw = t.yaw;
		w.length = 1.0, w.width = 0.6, w.leg_width = 0.05, w.texture = t.texture;
		tables.push_back(w);
	}
	return {eval::MapEvaluation::compute(world::World::load(SRC + "/config/worlds/paper_arena.ini").tables, tables, {}),
			std::move(fit)};
}

eval::MapEvaluation fitDataset(const std::string& preset)
{
	return fitDataset(preset, 1, [](baseline::TBaselineParams&) {}).first;
}
}  // namespace

// Regression floors on the shipped datasets (measured 2026-11-28: F1 1.00 at every noise
// level, centre RMSE 0.29 mm at default noise, 0.82 mm very noisy; doc/baseline.md).
TEST(BatchFit, PaperArenaDefaultNoise)
{
	const auto e = fitDataset("default");
	EXPECT_EQ(e.figures.f1, 1.0);
	EXPECT_LT(e.figures.rmse_m, 0.001);
	EXPECT_LT(e.figures.yaw_err_deg, 0.1);
}

TEST(BatchFit, PaperArenaVeryNoisy)
{
	const auto e = fitDataset("very-noisy");
	EXPECT_EQ(e.figures.f1, 1.0);
	EXPECT_LT(e.figures.rmse_m, 0.002);
}

// A log that drives the same path 20 times, with caps small enough that every touched cell
// is sampled: the fit keeps under a quarter of the contacts (16 per cell of the ~500 touched)
// and the map is as good.
TEST(BatchFit, ALongLogIsSampledPerCellAndMapsTheSame)
{
	const auto once = fitDataset("default", 1, [](baseline::TBaselineParams&) {}).second;
	const auto [e, fit] = fitDataset("default", 20, [](baseline::TBaselineParams& p) {
		p.contacts_per_cell = 16, p.sectors_per_cell = 512;
	});
	EXPECT_LT(fit.contacts.size(), 20 * once.contacts.size() / 4);
	EXPECT_EQ(e.figures.f1, 1.0);
	EXPECT_LT(e.figures.rmse_m, 0.001);
}

TEST(TBaselineParams, KnownTableFromTheModelSection)
{
	const auto dir = std::filesystem::temp_directory_path();
	const auto good = (dir / "whiskermap_baseline_model.ini").string();
	std::ifstream in(SRC + "/config/whisker-map.ini");
	std::string text((std::istreambuf_iterator<char>(in)), {});
	text.replace(text.find("table_length = 1.0"), 18, "table_length = 1.2");
	std::ofstream(good) << text;
	EXPECT_EQ(baseline::TBaselineParams::fromConfig(good).table_length, 1.2);
	const auto none = (dir / "whiskermap_baseline_none.ini").string();
	std::ofstream(none) << "[MetricMap]\nhierarchicalObjectMap_count=1\n";
	EXPECT_EQ(baseline::TBaselineParams::fromConfig(none).table_length, 1.0);  // built-in
	const auto bad = (dir / "whiskermap_baseline_bad.ini").string();
	std::ofstream(bad) << "[MetricMap_hierarchicalObjectMap_00_model]\ntable_length = long\n";
	try
	{
		baseline::TBaselineParams::fromConfig(bad);
		ADD_FAILURE() << "no error";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("whiskermap_baseline_bad.ini"), std::string::npos) << e.what();
	}
	EXPECT_THROW(baseline::TBaselineParams::fromConfig((dir / "nowhere.ini").string()), core::Error);
	for (const auto& f : {good, none, bad}) std::filesystem::remove(f);
}
