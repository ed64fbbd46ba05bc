// Issue 11's world keys: object classes and interior walls (parsing, errors, geometry).
#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/PathPlanner.h>
#include <whiskermap/world/WhiskerContact.h>
#include <whiskermap/world/WhiskerSimulator.h>
#include <whiskermap/world/World.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <type_traits>

using namespace whiskermap;
namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
const std::string ARENA = "[arena]\nx_min=0\nx_max=5\ny_min=0\ny_max=5\n";
const std::string CHAIR =
	"[table_3]\nclass=chair\nx=2.0\ny=1.0\nyaw_deg=10\nlength=0.42\nwidth=0.42\nleg_width=0.03\ntexture=0.5\n";
const std::string WALL = "[wall_0]\nx0=1.0\ny0=3.0\nx1=3.5\ny1=3.0\nthickness=0.1\ntexture=0.3\n";
const std::string TABLE =
	"[table_0]\nx=1.5\ny=2.0\nyaw_deg=0\nlength=1.0\nwidth=0.6\nleg_width=0.05\ntexture=0.7\n";

std::string writeTemp(const std::string& name, const std::string& text)
{
	const auto p = (fs::temp_directory_path() / ("whiskermap_walls_" + name + ".ini")).string();
	std::ofstream(p) << text;
	return p;
}

world::World load(const std::string& name, const std::string& text)
{
	const auto p = writeTemp(name, text);
	const auto w = world::World::load(p);
	fs::remove(p);
	return w;
}

std::string loadError(const std::string& name, const std::string& text)
{
	try
	{
		load(name, text);
	}
	catch (const core::Error& e)
	{
		fs::remove(writeTemp(name, ""));
		return e.what();
	}
	return "loaded";
}

std::string wall(const std::string& keys)
{
	return "[wall_0]\n" + keys + "\n";
}
}  // namespace

TEST(WorldWalls, LoadsTheIssueExample)
{
	const auto w = load("issue", ARENA + TABLE + CHAIR + WALL);
	ASSERT_EQ(w.tables.size(), 2u);
	EXPECT_EQ(w.tables[0].object_class.str(), "table");  // default
	EXPECT_EQ(w.tables[1].object_class.str(), "chair");
	EXPECT_DOUBLE_EQ(w.tables[1].leg_width, 0.03);
	ASSERT_EQ(w.walls.size(), 1u);
	EXPECT_DOUBLE_EQ(w.walls[0].x1, 3.5);
	EXPECT_DOUBLE_EQ(w.walls[0].thickness, 0.1);
	EXPECT_DOUBLE_EQ(w.walls[0].texture, 0.3);
	EXPECT_DOUBLE_EQ(w.walls[0].length(), 2.5);
	// Legs, the four arena walls, then the interior wall's slab (a wall: table -1).
	const auto obs = w.obstacles();
	ASSERT_EQ(obs.size(), 2u * 4 + 4 + 1);
	EXPECT_EQ(obs.back().table, -1);
	EXPECT_DOUBLE_EQ(obs.back().texture, 0.3);
	EXPECT_NEAR(obs.back().distance({2.0, 3.0}), 0, 1e-12);
	EXPECT_NEAR(obs.back().distance({2.0, 2.9}), 0.05, 1e-12);
	EXPECT_NEAR(obs.back().distance({0.7, 3.0}), 0.3, 1e-12);  // no end cap
}

TEST(WorldWalls, ObjectClassIsAnInlineLabel)
{
	static_assert(std::is_trivially_copyable_v<world::Table>);  // numpy records (python/)
	EXPECT_EQ(world::ObjectClass().str(), "table");
	EXPECT_EQ(world::ObjectClass("desk_2").str(), "desk_2");
	EXPECT_TRUE(world::ObjectClass("chair") == world::ObjectClass("chair"));
	EXPECT_TRUE(world::ObjectClass("chair") != world::ObjectClass("chairs"));
	EXPECT_THROW(world::ObjectClass("a b"), std::invalid_argument);
	EXPECT_THROW(world::ObjectClass(std::string(32, 'a')), std::invalid_argument);
	EXPECT_EQ(world::ObjectClass(std::string(31, 'a')).str(), std::string(31, 'a'));
}

TEST(WorldWalls, SaveWritesClassAndWallsAndLoadsBack)
{
	auto w = load("rt", ARENA + TABLE + CHAIR + WALL + "[wall_1]\nx0=0\ny0=4\nx1=5\ny1=4.5\nthickness=0.05\ntexture=0.4\n");
	const auto p = (fs::temp_directory_path() / "whiskermap_walls_saved.ini").string();
	w.save(p);
	const auto v = world::World::load(p);
	fs::remove(p);
	ASSERT_EQ(v.tables.size(), 2u);
	EXPECT_EQ(v.tables[0].object_class.str(), "table");
	EXPECT_EQ(v.tables[1].object_class.str(), "chair");
	ASSERT_EQ(v.walls.size(), 2u);
	for (size_t i = 0; i < 2; i++)
	{
		EXPECT_DOUBLE_EQ(v.walls[i].x0, w.walls[i].x0);
		EXPECT_DOUBLE_EQ(v.walls[i].y0, w.walls[i].y0);
		EXPECT_DOUBLE_EQ(v.walls[i].x1, w.walls[i].x1);
		EXPECT_DOUBLE_EQ(v.walls[i].y1, w.walls[i].y1);
		EXPECT_DOUBLE_EQ(v.walls[i].thickness, w.walls[i].thickness);
		EXPECT_DOUBLE_EQ(v.walls[i].texture, w.walls[i].texture);
	}
}

TEST(WorldWalls, AWorldWithoutThemSavesAsBefore)
{
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	const auto p = (fs::temp_directory_path() / "whiskermap_walls_plain.ini").string();
	w.save(p);
	std::ifstream f(p);
	std::stringstream text;
	text << f.rdbuf();
	fs::remove(p);
	EXPECT_EQ(text.str().find("class="), std::string::npos);
	EXPECT_EQ(text.str().find("[wall_"), std::string::npos);
}

TEST(WorldWalls, TiledRepeatsTheWalls)
{
	const auto w = load("tiled", ARENA + TABLE + WALL).tiled(2, 1);
	ASSERT_EQ(w.walls.size(), 2u);
	EXPECT_DOUBLE_EQ(w.walls[1].x0, 6.0);
	EXPECT_DOUBLE_EQ(w.walls[1].y1, 3.0);
}

TEST(WorldWalls, ErrorsNameFileSectionAndProblem)
{
	const std::string ends = "x0=1\ny0=3\nx1=3\ny1=3\n";
	EXPECT_NE(loadError("class", ARENA + TABLE + "class=big-chair\n").find("[table_0] class: 'big-chair' is not a class name"), std::string::npos);
	EXPECT_NE(loadError("classlong", ARENA + TABLE + "class=" + std::string(32, 'c') + "\n").find("is not a class name (1 to 31"), std::string::npos);
	EXPECT_EQ(loadError("class31", ARENA + TABLE + "class=" + std::string(31, 'c') + "\n"), "loaded");
	EXPECT_NE(loadError("classempty", ARENA + TABLE + "class=\n").find("[table_0] class: '' is not a class name"), std::string::npos);
	EXPECT_NE(loadError("zero", ARENA + wall("x0=1\ny0=3\nx1=1\ny1=3\nthickness=0.1\ntexture=0.3")).find("[wall_0]: wall has zero length"), std::string::npos);
	EXPECT_NE(loadError("outside", ARENA + wall("x0=1\ny0=3\nx1=6\ny1=3\nthickness=0.1\ntexture=0.3")).find("[wall_0]: wall end point outside the arena"), std::string::npos);
	EXPECT_NE(loadError("thin", ARENA + wall(ends + "thickness=0\ntexture=0.3")).find("[wall_0] thickness"), std::string::npos);
	EXPECT_NE(loadError("thick", "[arena]\nx_min=0\nx_max=3\ny_min=0\ny_max=3\n" + wall("x0=0\ny0=1\nx1=3\ny1=1\nthickness=1.6\ntexture=0.3")).find("[wall_0] thickness: wall thicker than half the arena"), std::string::npos);
	EXPECT_NE(loadError("thickrange", ARENA + wall(ends + "thickness=2.1\ntexture=0.3")).find("[wall_0] thickness"), std::string::npos);
	EXPECT_NE(loadError("nan", ARENA + wall("x0=1\ny0=nan\nx1=3\ny1=3\nthickness=0.1\ntexture=0.3")).find("[wall_0] y0: 'nan' is not finite"), std::string::npos);
	EXPECT_NE(loadError("texture", ARENA + wall(ends + "thickness=0.1\ntexture=1.5")).find("[wall_0] texture"), std::string::npos);
	EXPECT_NE(loadError("missing", ARENA + wall(ends + "texture=0.3")).find("[wall_0] thickness: missing required key"), std::string::npos);
	EXPECT_NE(loadError("unknown", ARENA + wall(ends + "thickness=0.1\ntexture=0.3\nheight=2")).find("[wall_0] height: unknown key"), std::string::npos);
	EXPECT_NE(loadError("name", ARENA + "[wall_x]\n" + ends).find("wall sections must be named wall_N"), std::string::npos);
	const auto e = loadError("onwall", ARENA + wall("x0=0\ny0=2.2\nx1=5\ny1=2.2\nthickness=0.1\ntexture=0.3") + TABLE);
	EXPECT_NE(e.find("[table_0]: object overlaps [wall_0]"), std::string::npos) << e;
	EXPECT_NE(e.find("whiskermap_walls_onwall.ini"), std::string::npos) << e;
	// Walls may touch the arena's walls and each other.
	EXPECT_EQ(loadError("touch", ARENA + wall("x0=0\ny0=3\nx1=5\ny1=3\nthickness=0.1\ntexture=0.3") +
								"[wall_1]\nx0=2.5\ny0=3\nx1=2.5\ny1=5\nthickness=0.1\ntexture=0.3\n"),
			  "loaded");
}

TEST(WorldWalls, AFixedWhiskerHitsTheWallsNearFace)
{
	// Wall along y = 3 (0.1 thick): its lower face is y = 2.95, outward normal -y. A whisker
	// from (2, 2.5) pointing +y crosses it 0.45 from the pivot.
	const auto w = load("face", ARENA + WALL);
	const auto obs = w.obstacles();
	const auto c = world::WhiskerContact::first({2.0, 2.5}, 0.6, M_PI / 2, M_PI / 2, obs);
	ASSERT_TRUE(c);
	EXPECT_NEAR(c->r, 0.45, 1e-9);
	EXPECT_NEAR(c->point.x(), 2.0, 1e-9);
	EXPECT_NEAR(c->point.y(), 2.95, 1e-9);
	EXPECT_NEAR(c->normal, -M_PI / 2, 1e-9);
	EXPECT_EQ(c->obstacle, int(obs.size()) - 1);
	EXPECT_DOUBLE_EQ(obs[c->obstacle].texture, 0.3);
}

TEST(WorldWalls, ASweepingWhiskerTipMeetsADiagonalWall)
{
	// Wall (1, 1)-(3, 3), 0.2 thick: the face towards (3, 1) lies on x - y = 0.1 * sqrt(2),
	// normal angle -45 deg. A whisker of length 1.5 from (3, 1) sweeping from 0 deg towards
	// 180 deg first touches it with its tip at angle a where 3 + 1.5 cos a - (1 + 1.5 sin a)
	// = 0.1 sqrt(2), i.e. sqrt(2) cos(a + 45 deg) = (0.1 sqrt(2) - 2) / 1.5: a = 106.2 deg (the
	// slab's corners are all beyond reach, 1.93 m away).
	const auto w = load("diag", ARENA + wall("x0=1\ny0=1\nx1=3\ny1=3\nthickness=0.2\ntexture=0.45"));
	const auto obs = w.obstacles();
	const auto c = world::WhiskerContact::first({3.0, 1.0}, 1.5, 0, M_PI, obs);
	ASSERT_TRUE(c);
	const double a = std::acos((0.1 * std::sqrt(2.0) - 2) / (1.5 * std::sqrt(2.0))) - M_PI / 4;
	EXPECT_NEAR(c->angle, a, 1e-6);
	EXPECT_NEAR(c->r, 1.5, 1e-9);
	EXPECT_NEAR(c->point.x() - c->point.y(), 0.1 * std::sqrt(2.0), 1e-6);
	EXPECT_NEAR(c->normal, -M_PI / 4, 1e-9);
	EXPECT_DOUBLE_EQ(obs[c->obstacle].texture, 0.45);
}

TEST(WorldWalls, TheSimulatorAndPlannerTreatInteriorWallsAsWalls)
{
	const auto w = load("sim", ARENA + WALL);
	const auto robot = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
	world::WhiskerSimulator sim(w, robot, {}, 1);
	EXPECT_FALSE(sim.poseIsFree({2.0, 3.0, 0}));  // body on the wall
	EXPECT_TRUE(sim.poseIsFree({2.0, 2.0, 0}));
	std::vector<world::WhiskerSimulator::Truth> truth;
	const auto o = sim.sense({2.0, 3.0 - 0.05 - robot.radius - 0.02, M_PI / 2}, mrpt::Clock::fromDouble(1e9), &truth);
	size_t onWall = 0;
	for (const auto& s : o->toShapelets({2.0, 3.0 - 0.05 - robot.radius - 0.02, M_PI / 2}))
	{
		EXPECT_TRUE(truth[s.whisker].wall);
		if (std::abs(s.y - 2.95) < 1e-9)
		{
			onWall++;
			EXPECT_DOUBLE_EQ(s.texture, 0.3);
		}
	}
	EXPECT_GT(onWall, 0u);
	const world::PathPlanner planner(w, robot.radius);
	EXPECT_FALSE(planner.free({2.0, 3.0}));
	EXPECT_FALSE(planner.segmentFree({2.0, 2.0}, {2.0, 4.0}));
	EXPECT_TRUE(planner.free({2.0, 2.0}));
}
