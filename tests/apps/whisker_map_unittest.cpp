// whisker-map driven in-process on a shipped dataset: its 3-D scene reloads with MRPT and
// holds the expected objects.
#include <gtest/gtest.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/cli/WhiskerMapApp.h>
#include <whiskermap/eval/TableCsv.h>
#include <whiskermap/eval/WallEvaluation.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/maps/MapCsv.h>
#include <whiskermap/obs/RawlogReader.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

int runWhiskerMap(std::vector<std::string> args)
{
	args.insert(args.begin(), "whisker-map");
	std::vector<char*> argv;
	for (auto& a : args) argv.push_back(a.data());
	return whiskermap::cli::WhiskerMapApp::main(static_cast<int>(argv.size()), argv.data());
}

std::string slurp(const std::string& path)
{
	std::ifstream f(path);
	return std::string((std::istreambuf_iterator<char>(f)), {});
}
}  // namespace

TEST(WhiskerMap, StreamingRunEqualsTheMapLibrary)
{
	// whisker-map streams the rawlog (the per-pose mode solving steps on 2 threads); the map
	// class used directly (insertObservation, in order) must give the very same CSVs.
	const std::string data = SRC + "/datasets/paper_arena/default.rawlog";
	for (const std::string mode : {"lasting", "per_pose"})
	{
		const auto out = (fs::temp_directory_path() / ("whiskermap_stream_test_" + mode)).string();
		fs::remove_all(out);
		ASSERT_EQ(runWhiskerMap({"-q", "-j", "2", "--mode", mode, "-i", data, "-o", out}), 0);

		mrpt::maps::CMultiMetricMap mm(whiskermap::maps::MapConfig::load(SRC + "/config/whisker-map.ini"));
		auto map = mm.mapByClass<whiskermap::maps::CHierarchicalObjectMap>();
		map->insertionOptions.mode = mode == "lasting" ? whiskermap::maps::CHierarchicalObjectMap::TInsertionOptions::TMode::Lasting
													   : whiskermap::maps::CHierarchicalObjectMap::TInsertionOptions::TMode::PerPose;
		for (const auto& s : whiskermap::obs::RawlogReader::read(data).sweeps)
			mm.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		map->saveMetricMapRepresentationToFile(out + "/lib");
		EXPECT_EQ(slurp(out + "/map_tables.csv"), slurp(out + "/lib_map_tables.csv")) << mode;
		EXPECT_EQ(slurp(out + "/map_candidates.csv"), slurp(out + "/lib_map_candidates.csv")) << mode;
		EXPECT_GT(slurp(out + "/map_tables.csv").size(), 300u) << mode;
		if (mode == "per_pose")
		{
			EXPECT_EQ(slurp(out + "/per_pose_tables.csv"), slurp(out + "/lib_per_pose_tables.csv"));
			EXPECT_GT(slurp(out + "/per_pose_tables.csv").size(), 1000u);
		}
		fs::remove_all(out);
	}
}

TEST(WhiskerMap, SceneReloadsWithTheSupportedTables)
{
	const auto out = (fs::temp_directory_path() / "whiskermap_scene_test").string();
	fs::remove_all(out);
	ASSERT_EQ(runWhiskerMap({"-q", "-i", SRC + "/datasets/paper_arena/noiseless.rawlog", "-o", out}), 0);
	const std::string text = slurp(out + "/summary.json");
	std::smatch m;
	ASSERT_TRUE(std::regex_search(text, m, std::regex("\"map_tables\": (\\d+)")));
	const size_t supported = std::stoul(m[1]);
	ASSERT_GE(supported, 6u);

	mrpt::opengl::COpenGLScene scene;
	ASSERT_TRUE(scene.loadFromFile(out + "/map.3Dscene"));
	auto objs = scene.getByName("whiskermap");
	ASSERT_TRUE(objs);
	auto set = std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(objs);
	ASSERT_TRUE(set);
	size_t tables = 0, legs = 0;
	for (const auto& o : *set)
		if (o && o->getName() == "table")
		{
			tables++;
			for (const auto& part : *std::dynamic_pointer_cast<mrpt::opengl::CSetOfObjects>(o))
				legs += part->getName() == "leg";
		}
	EXPECT_EQ(tables, supported);
	EXPECT_EQ(legs, 4 * supported);
	EXPECT_TRUE(scene.getByName("contacts"));
	EXPECT_TRUE(scene.getByName("robot_path"));
	fs::remove_all(out);
}

namespace
{
double jsonNumber(const std::string& json, const std::string& key)
{
	std::smatch m;
	if (!std::regex_search(json, m, std::regex("\"" + key + "\": ([-0-9.eE]+)"))) return NAN;
	return std::stod(m[1]);
}
}  // namespace

TEST(WhiskerMap, OfficeWithTheObjectCatalogueAboveItsFloors)
{
	// whisker-map with config/office-map.ini (the object catalogue) on the office, evaluated
	// within classes: F1, class accuracy and dimension errors may not fall past the figures
	// measured on 2026-11-28 (doc/results.md, "The office") with a stated margin.
	//   dataset     F1 (floor)     class accuracy (floor)
	//   noiseless   1.000 (1.00)   1.000 (1.00)
	//   default     1.000 (0.95)   1.000 (0.95)   (0.963 before walls, doc/results.md "With walls")
	// Without the catalogue the same runs score F1 0.353 (only the 1.0 x 0.6 m tables).
	// With walls (office-map.ini's `walls = true`) map_walls.csv is written and read back by
	// whisker-eval's reader: wall length recall 0.937 (floor 0.90), precision 0.994 (0.95).
	const whiskermap::world::World office = whiskermap::world::World::load(SRC + "/config/worlds/office.ini");
	for (const auto& [dataset, f1] : {std::pair<const char*, double>{"noiseless", 1.0}, {"default", 0.95}})
	{
		const auto out = (fs::temp_directory_path() / (std::string("whiskermap_office_") + dataset)).string();
		fs::remove_all(out);
		ASSERT_EQ(runWhiskerMap({"-q", "--seed", "1", "-c", SRC + "/config/office-map.ini", "-i",
								 SRC + "/datasets/office/" + dataset + ".rawlog", "--world", SRC + "/config/worlds/office.ini",
								 "-o", out}),
				  0);
		const std::string metrics = slurp(out + "/metrics.json");
		EXPECT_GE(jsonNumber(metrics, "f1"), f1) << dataset;
		EXPECT_GE(jsonNumber(metrics, "class_accuracy"), 0.95) << dataset;
		EXPECT_LE(jsonNumber(metrics, "length_err_m"), 0.01) << dataset;
		EXPECT_NE(slurp(out + "/map_tables.csv").find(",legs,sd_x,sd_y,sd_yaw_deg,class\n"), std::string::npos) << dataset;
		std::vector<whiskermap::world::Wall> walls;
		for (const auto& row : whiskermap::eval::TableCsv::readWalls(out + "/map_walls.csv")) walls.push_back(row.wall);
		const auto w = whiskermap::eval::WallEvaluation::compute(
			whiskermap::eval::WallEvaluation::trueWalls(office), walls, 0.15, 20);
		EXPECT_GE(w.recall, 0.90) << dataset;
		EXPECT_GE(w.precision, 0.95) << dataset;
		fs::remove_all(out);
	}
}

TEST(WhiskerMap, RegressionFloorsOnTheShippedDatasets)
{
	// whisker-map (seed 1) on each shipped dataset, evaluated against the paper arena, in
	// both modes: map_tables.csv scored as written may not lose F1, nor its centre or yaw
	// error grow, past the figures measured on 2026-12-01 with a stated margin (doc/results.md;
	// the lasting map's reported pose and very-noisy revisions, issue 7).
	//   lasting map:  dataset     F1 (floor)   RMSE m (ceiling)    yaw deg (ceiling)
	//                 noiseless   1.00 (1.00)  0.00000 (0.0005)    0.0001 (0.01)
	//                 default     1.00 (1.00)  0.00030 (0.0008)    0.020 (0.06)
	//                 very-noisy  1.00 (1.00)  0.00136 (0.0035)    0.092 (0.25)
	//   per-pose mode: the paper's; the same F1 and RMSE floors as before the lasting map (F1
	//   0.90 lets one table go spurious, not one go missing as well), per-pose local F1 >= 0.08,
	//   and yaw ceilings at about 3x the 2026-12-01 figures (0.12, 0.35, 0.90 deg).
	struct Floor
	{
		const char* mode;
		const char* dataset;
		double f1, rmse, yaw, localF1;
	};
	for (const Floor& f :
		 {Floor{"lasting", "noiseless", 1.0, 0.0005, 0.01, -1}, Floor{"lasting", "default", 1.0, 0.0008, 0.06, -1},
		  Floor{"lasting", "very-noisy", 1.0, 0.0035, 0.25, -1}, Floor{"per_pose", "noiseless", 0.90, 0.0090, 0.4, 0.08},
		  Floor{"per_pose", "default", 0.90, 0.0110, 1.0, 0.08}, Floor{"per_pose", "very-noisy", 0.90, 0.0250, 2.5, 0.08}})
	{
		const std::string what = std::string(f.mode) + " " + f.dataset;
		const auto out = (fs::temp_directory_path() / (std::string("whiskermap_floor_") + f.mode + f.dataset)).string();
		fs::remove_all(out);
		ASSERT_EQ(runWhiskerMap({"-q", "--seed", "1", "--mode", f.mode, "-i", SRC + "/datasets/paper_arena/" + f.dataset + ".rawlog",
								 "--world", SRC + "/config/worlds/paper_arena.ini", "-o", out}),
				  0);
		const std::string metrics = slurp(out + "/metrics.json");
		EXPECT_GE(jsonNumber(metrics, "f1"), f.f1) << what;
		EXPECT_LE(jsonNumber(metrics, "rmse_m"), f.rmse) << what;
		EXPECT_LE(jsonNumber(metrics, "yaw_err_deg"), f.yaw) << what;
		if (f.localF1 >= 0)
		{
			const std::string local = metrics.substr(metrics.find("\"local\""));
			EXPECT_GE(jsonNumber(local, "f1"), f.localF1) << what;
		}
		fs::remove_all(out);
	}
}

// map_walls.csv as whisker-map writes it reads back with whisker-eval's reader (--walls).
TEST(WhiskerMap, WallsCsvReadsBackInWhiskerEval)
{
	const fs::path dir = fs::temp_directory_path() / "whiskermap_walls_csv";
	fs::create_directories(dir);
	std::vector<whiskermap::model::LastingState::StoredWall> walls(2);
	walls[0].wall = {0.5, 1.0, 3.0, 1.0, 0.1, 0.3};
	walls[0].existence = 0.97;
	walls[1].wall = {1.0, 2.0, 1.0, 4.5, 0.1, 0.3};
	walls[1].existence = 1;
	const std::string path = (dir / "map_walls.csv").string();
	whiskermap::maps::MapCsv::writeWalls(path, walls);
	const auto rows = whiskermap::eval::TableCsv::readWalls(path);
	ASSERT_EQ(rows.size(), 2u);
	EXPECT_NEAR(rows[0].wall.x1, 3.0, 1e-6);
	EXPECT_NEAR(rows[0].wall.thickness, 0.1, 1e-6);
	EXPECT_NEAR(rows[0].existence, 0.97, 1e-6);
	EXPECT_NEAR(rows[1].wall.length(), 2.5, 1e-6);
	fs::remove_all(dir);
}
