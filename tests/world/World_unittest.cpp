#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/World.h>

#include <filesystem>
#include <fstream>

using namespace whiskermap;
namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
const std::string ARENA = "[arena]\nx_min=0\nx_max=5\ny_min=0\ny_max=5\n";
const std::string TABLE0 =
	"[table_0]\nx=1.5\ny=2.0\nyaw_deg=30\nlength=1.2\nwidth=0.6\nleg_width=0.05\ntexture=0.7\n";

std::string writeTemp(const std::string& name, const std::string& text)
{
	const auto p = (fs::temp_directory_path() / ("whiskermap_world_" + name + ".ini")).string();
	std::ofstream(p) << text;
	return p;
}

std::string loadError(const std::string& name, const std::string& text)
{
	const auto p = writeTemp(name, text);
	try
	{
		world::World::load(p);
	}
	catch (const core::Error& e)
	{
		fs::remove(p);
		return e.what();
	}
	fs::remove(p);
	return "loaded";
}
}  // namespace

TEST(World, LoadsTheIssueExampleIncludingInlineComments)
{
	const auto p = writeTemp("ok", ARENA + TABLE0 + "; comment\n");
	const auto w = world::World::load(p);
	fs::remove(p);
	ASSERT_EQ(w.tables.size(), 1u);
	EXPECT_DOUBLE_EQ(w.x_max, 5);
	EXPECT_DOUBLE_EQ(w.tables[0].yaw, core::deg2rad(30));
	EXPECT_DOUBLE_EQ(w.tables[0].leg_width, 0.05);
	EXPECT_DOUBLE_EQ(w.wall_texture, 0.3);  // optional key, default
}

TEST(World, PaperArenaHasSixEqualTables)
{
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	ASSERT_EQ(w.tables.size(), 6u);
	for (const auto& t : w.tables)
	{
		EXPECT_EQ(t.length, w.tables[0].length);
		EXPECT_EQ(t.width, w.tables[0].width);
		EXPECT_EQ(t.texture, w.tables[0].texture);
	}
	EXPECT_EQ(w.obstacles().size(), 6u * 4 + 4);  // legs + walls
}

TEST(World, SaveLoadsBackToTheSameValues)
{
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	const auto p = (fs::temp_directory_path() / "whiskermap_world_saved.ini").string();
	w.save(p);
	const auto v = world::World::load(p);
	fs::remove(p);
	ASSERT_EQ(v.tables.size(), w.tables.size());
	for (size_t i = 0; i < w.tables.size(); i++)
	{
		EXPECT_NEAR(v.tables[i].x, w.tables[i].x, 1e-9);
		EXPECT_NEAR(v.tables[i].yaw, w.tables[i].yaw, 1e-9);
	}
}

TEST(World, ErrorsNameFileSectionAndKey)
{
	EXPECT_NE(loadError("missing", ARENA + "[table_0]\nx=1.5\n").find("[table_0] y: missing required key"), std::string::npos);
	EXPECT_NE(loadError("unknownkey", ARENA + TABLE0 + "colour=red\n").find("[table_0] colour: unknown key"), std::string::npos);
	EXPECT_NE(loadError("unknownsec", ARENA + TABLE0 + "[chair_0]\nx=1\n").find("[chair_0]: unknown section"), std::string::npos);
	EXPECT_NE(loadError("badname", ARENA + "[table_x]\nx=1\n").find("table_N"), std::string::npos);
	EXPECT_NE(loadError("badnum", ARENA + "[table_0]\nx=one\n").find("[table_0] x: 'one' is not a number"), std::string::npos);
	EXPECT_NE(loadError("noarena", TABLE0).find("[arena]: missing section"), std::string::npos);
	EXPECT_NE(loadError("flip", "[arena]\nx_min=5\nx_max=0\ny_min=0\ny_max=5\n").find("x_max: must be greater"), std::string::npos);
	EXPECT_NE(loadError("texture", ARENA + "[table_0]\nx=1.5\ny=2.0\nyaw_deg=30\nlength=1.2\nwidth=0.6\nleg_width=0.05\ntexture=1\n").find("texture"), std::string::npos);
	EXPECT_NE(loadError("outside", ARENA + "[table_0]\nx=0.3\ny=2.0\nyaw_deg=0\nlength=1.2\nwidth=0.6\nleg_width=0.05\ntexture=0.7\n").find("outside the arena"), std::string::npos);
	const std::string t1 = "[table_1]\nx=1.8\ny=2.1\nyaw_deg=0\nlength=1.2\nwidth=0.6\nleg_width=0.05\ntexture=0.7\n";
	const auto e = loadError("overlap", ARENA + TABLE0 + t1);
	EXPECT_NE(e.find("[table_1]: table overlaps [table_0]"), std::string::npos) << e;
	EXPECT_NE(e.find("whiskermap_world_overlap.ini"), std::string::npos) << e;
	EXPECT_EQ(loadError("nofile-does-not-exist/../x", "").find("loaded"), std::string::npos);
}

TEST(Trajectory, PaperGridIsTenByTenPositionsTimesFourHeadings)
{
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	const auto poses = world::Trajectory::paperGrid(w);
	ASSERT_EQ(poses.size(), 400u);
	EXPECT_NEAR(poses[0].x(), 0.2, 1e-12);
	EXPECT_NEAR(poses[0].y(), 0.2, 1e-12);
	EXPECT_NEAR(poses[3].phi(), -M_PI / 2, 1e-12);  // 270 deg, wrapped
	EXPECT_NEAR(poses[399].x(), 3.8, 1e-12);
	EXPECT_NEAR(poses[399].y(), 3.8, 1e-12);
}

TEST(Trajectory, PathFileParsesAndRejectsBadLines)
{
	const auto good = writeTemp("path", "% x y yaw\n1 2 90\n\n# note\n3 4 -45\n");
	const auto poses = world::Trajectory::readPathFile(good);
	ASSERT_EQ(poses.size(), 2u);
	EXPECT_NEAR(poses[0].phi(), M_PI / 2, 1e-12);
	const auto bad = writeTemp("badpath", "1 2 90\n1 2\n");
	try
	{
		world::Trajectory::readPathFile(bad);
		ADD_FAILURE() << "no error";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos);
	}
	fs::remove(good);
	fs::remove(bad);
}

// Regression (issue 8): a path file was read with unbounded lines into memory, and far or
// non-finite poses were accepted (they hung the spatial code downstream).
TEST(Trajectory, PathFileLinesAndPosesAreBounded)
{
	auto errorOf = [](const std::string& name, const std::string& text) -> std::string {
		const auto path = writeTemp(name, text);
		std::string e;
		try
		{
			world::Trajectory::pathFileSource(path);
		}
		catch (const core::Error& x)
		{
			e = x.what();
		}
		fs::remove(path);
		return e;
	};
	EXPECT_NE(errorOf("long", "1 2 0\n" + std::string(100000, '1')).find("line 2: longer than 4096 bytes"), std::string::npos);
	EXPECT_NE(errorOf("nul", std::string("1 2 0\n1 2\0 0\n", 13)).find("line 2: holds a control byte 0"), std::string::npos);
	for (const char* far : {"2.1e9 0 0", "0 1e300 0", "nan 0 0", "0 0 inf", "0 0 1e9"})
		EXPECT_NE(errorOf("far", std::string("1 1 0\n") + far + "\n").find("line 2: expected 'x y yaw_deg'"), std::string::npos) << far;
	EXPECT_NE(errorOf("empty", "% nothing\n").find("holds no poses"), std::string::npos);
	const auto ok = writeTemp("ok", "1 1 0\n-99999 99999 3600\n");
	auto src = world::Trajectory::pathFileSource(ok);
	EXPECT_EQ(src->size(), 2u);
	mrpt::poses::CPose2D p;
	EXPECT_TRUE(src->next(p) && src->next(p) && !src->next(p));
	src->rewind();
	EXPECT_TRUE(src->next(p));
	EXPECT_DOUBLE_EQ(p.x(), 1);
	fs::remove(ok);
}
