// whisker-map driven in-process on a shipped dataset: its 3-D scene reloads with MRPT and
// holds the expected objects.
#include <gtest/gtest.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <whiskermap/cli/WhiskerMapApp.h>

#include <filesystem>
#include <fstream>
#include <regex>

namespace fs = std::filesystem;

TEST(WhiskerMap, SceneReloadsWithTheSupportedTables)
{
	const std::string src = WHISKERMAP_SOURCE_DIR;
	const auto out = (fs::temp_directory_path() / "whiskermap_scene_test").string();
	fs::remove_all(out);
	std::vector<std::string> args = {"whisker-map", "-q", "-i", src + "/datasets/paper_arena/noiseless.rawlog", "-o", out};
	std::vector<char*> argv;
	for (auto& a : args) argv.push_back(a.data());
	ASSERT_EQ(whiskermap::cli::WhiskerMapApp::main(static_cast<int>(argv.size()), argv.data()), 0);

	std::ifstream summary(out + "/summary.json");
	const std::string text((std::istreambuf_iterator<char>(summary)), {});
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
	EXPECT_TRUE(set->getByName("shapelets"));
	EXPECT_TRUE(scene.getByName("robot_path"));
	fs::remove_all(out);
}
