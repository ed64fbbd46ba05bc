// Regression tests of issue 8: every .ini loader refuses ambiguous or unknown sections,
// naming the file and the line.
#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/World.h>

#include <filesystem>
#include <fstream>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

std::string slurp(const std::string& path)
{
	std::ifstream f(path);
	return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

/** The error of `load` on a file holding `text`, or "" when it loads. */
template <class Load>
std::string error(const std::string& text, Load load)
{
	const auto path = (std::filesystem::temp_directory_path() / ("whiskermap_strict_" + std::to_string(::getpid()) + ".ini")).string();
	std::ofstream(path) << text;
	std::string e;
	try
	{
		load(path);
	}
	catch (const core::Error& x)
	{
		e = x.what();
		EXPECT_EQ(e.rfind(path + ": line ", 0), 0u) << e;
		EXPECT_EQ(e.find('\n'), std::string::npos) << e;
	}
	std::filesystem::remove(path);
	return e;
}

const auto worldFile = [](const std::string& p) { world::World::load(p); };
const auto robotFile = [](const std::string& p) { world::Robot::load(p); };
const auto mapConfig = [](const std::string& p) { maps::MapConfig::load(p); };

const std::string ARENA = "[arena]\nx_min=0\nx_max=5\ny_min=0\ny_max=5\n";
std::string table(const std::string& name, double x)
{
	return "[" + name + "]\nx=" + std::to_string(x) + "\ny=2\nyaw_deg=0\nlength=1\nwidth=0.6\nleg_width=0.05\ntexture=0.5\n";
}
}  // namespace

TEST(StrictIni, ShippedFilesLoad)
{
	EXPECT_EQ(error(slurp(SRC + "/config/worlds/paper_arena.ini"), worldFile), "");
	EXPECT_EQ(error(slurp(SRC + "/config/robots/scratchbot.ini"), robotFile), "");
	EXPECT_EQ(error(slurp(SRC + "/config/whisker-map.ini"), mapConfig), "");
}

TEST(StrictIni, AmbiguousTableIndicesAreRefused)  // [table_01] beside [table_1] dropped a table
{
	const auto e = error(ARENA + table("table_1", 1.5) + table("table_01", 3.5), worldFile);
	EXPECT_NE(e.find("line 14: [table_01]: table sections must be named table_N"), std::string::npos) << e;
	const auto huge = error(ARENA + table("table_99999999999999999999", 1.5), worldFile);  // printed "stol"
	EXPECT_NE(huge.find("line 6: [table_99999999999999999999]: table sections must be named"), std::string::npos) << huge;
	EXPECT_NE(error(ARENA + table("table_1", 1.5) + table("table_1", 3.5), worldFile).find("appears twice"), std::string::npos);
}

TEST(StrictIni, UnknownSectionsAreRefusedWithTheirLine)  // [bogus] in whisker-map.ini was accepted
{
	const auto e = error(slurp(SRC + "/config/whisker-map.ini") + "\n[bogus]\nx=1\n", mapConfig);
	EXPECT_NE(e.find("[bogus]: unknown section"), std::string::npos) << e;
	EXPECT_NE(error(ARENA + "[tables]\n", worldFile).find("line 6: [tables]: unknown section"), std::string::npos);
	const auto huge = error("[MetricMap]\nhierarchicalObjectMap_count=100000000000\n", mapConfig);
	EXPECT_NE(huge.find("hierarchicalObjectMap_count"), std::string::npos) << huge;
}

TEST(StrictIni, RobotWhiskerSectionsMustMatchTheCount)
{
	const std::string head = "[robot]\nradius=0.1\nwhisker_count=1\n[whisker_0]\nmount_x=0\nmount_y=0\nsweep_start_deg=90\nsweep_end_deg=0\nlength=0.5\n";
	EXPECT_EQ(error(head, robotFile), "");
	EXPECT_NE(error(head + "[whisker_00]\n", robotFile).find("line 10: [whisker_00]: not whisker_0 .. whisker_0"), std::string::npos);
	EXPECT_NE(error(head + "[whisker_99999999999999999999]\n", robotFile).find("[whisker_99999999999999999999]: not whisker_0"),
			  std::string::npos);
}
