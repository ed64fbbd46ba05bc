// whisker-map driven in-process on a shipped dataset: its 3-D scene reloads with MRPT and
// holds the expected objects.
#include <gtest/gtest.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/cli/WhiskerMapApp.h>
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

TEST(WhiskerMap, StreamingParallelRunEqualsTheMapLibrary)
{
	// whisker-map streams the rawlog and solves steps on 2 threads; the map class used
	// directly (insertObservation, in order) must give the very same per-pose and map CSVs.
	const std::string data = SRC + "/datasets/paper_arena/default.rawlog";
	const auto out = (fs::temp_directory_path() / "whiskermap_stream_test").string();
	fs::remove_all(out);
	ASSERT_EQ(runWhiskerMap({"-q", "-j", "2", "-i", data, "-o", out}), 0);

	mrpt::maps::CMultiMetricMap mm(whiskermap::maps::MapConfig::load(SRC + "/config/whisker-map.ini"));
	auto map = mm.mapByClass<whiskermap::maps::CHierarchicalObjectMap>();
	for (const auto& s : whiskermap::obs::RawlogReader::read(data).sweeps)
		mm.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
	map->saveMetricMapRepresentationToFile(out + "/lib");
	EXPECT_EQ(slurp(out + "/per_pose_tables.csv"), slurp(out + "/lib_per_pose_tables.csv"));
	EXPECT_EQ(slurp(out + "/map_tables.csv"), slurp(out + "/lib_map_tables.csv"));
	EXPECT_GT(slurp(out + "/per_pose_tables.csv").size(), 1000u);
	fs::remove_all(out);
}

TEST(WhiskerMap, SceneReloadsWithTheSupportedTables)
{
	const auto out = (fs::temp_directory_path() / "whiskermap_scene_test").string();
	fs::remove_all(out);
	ASSERT_EQ(runWhiskerMap({"-q", "-i", SRC + "/datasets/paper_arena/noiseless.rawlog", "-o", out}), 0);
	const std::string text = slurp(out + "/summary.json");
	std::smatch m;
	ASSERT_TRUE(std::regex_search(text, m, std::regex("\"map_objects_supported\": (\\d+)")));
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

TEST(WhiskerMap, RegressionFloorsOnTheShippedDatasets)
{
	// whisker-map (seed 1) on each shipped dataset, evaluated against the paper arena: the
	// consolidated map's F1 may not drop, nor its centre error grow, past the values
	// measured on 2026-11-22 with a stated margin (doc/results.md):
	//   dataset     F1 (floor)   RMSE m (ceiling)      per-pose local F1 (floor)
	//   noiseless   1.00 (0.90)  0.0045 (0.0090)       0.133 (0.08)
	//   default     1.00 (0.90)  0.0053 (0.0110)       0.098 (0.08)
	//   very-noisy  1.00 (0.90)  0.0116 (0.0250)       0.098 (0.08)
	// A floor of 0.90 lets one table go spurious (F1 0.92) but not one go missing as well.
	struct Floor
	{
		const char* dataset;
		double f1, rmse, localF1;
	};
	for (const Floor& f : {Floor{"noiseless", 0.90, 0.0090, 0.08}, Floor{"default", 0.90, 0.0110, 0.08},
						   Floor{"very-noisy", 0.90, 0.0250, 0.08}})
	{
		const auto out = (fs::temp_directory_path() / (std::string("whiskermap_floor_") + f.dataset)).string();
		fs::remove_all(out);
		ASSERT_EQ(runWhiskerMap({"-q", "--seed", "1", "-i", SRC + "/datasets/paper_arena/" + f.dataset + ".rawlog",
								 "--world", SRC + "/config/worlds/paper_arena.ini", "-o", out}),
				  0);
		const std::string metrics = slurp(out + "/metrics.json");
		EXPECT_GE(jsonNumber(metrics, "f1"), f.f1) << f.dataset;
		EXPECT_LE(jsonNumber(metrics, "rmse_m"), f.rmse) << f.dataset;
		const std::string local = metrics.substr(metrics.find("\"local\""));
		EXPECT_GE(jsonNumber(local, "f1"), f.localF1) << f.dataset;
		fs::remove_all(out);
	}
}
