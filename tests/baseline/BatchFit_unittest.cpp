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

eval::MapEvaluation fitDataset(const std::string& preset)
{
	const auto sweeps = obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog").sweeps;
	const auto fit = baseline::BatchFit::run(sweeps, baseline::TBaselineParams::fromConfig(SRC + "/config/whisker-map.ini"));
	std::vector<world::Table> tables;
	for (const auto& t : fit.tables)
	{
		world::Table w;
		w.x = t.centre.x(), w.y = t.centre.y(), w.yaw = t.yaw;
		w.length = 1.0, w.width = 0.6, w.leg_width = 0.05, w.texture = t.texture;
		tables.push_back(w);
	}
	return eval::MapEvaluation::compute(world::World::load(SRC + "/config/worlds/paper_arena.ini").tables, tables, {});
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
