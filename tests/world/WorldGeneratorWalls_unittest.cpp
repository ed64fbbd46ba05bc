// Issue 11's generated worlds (walls, mixed_classes, near_walls): the shipped seeds obey their
// category, and the same seed gives the same walls.
#include <gtest/gtest.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>
#include <whiskermap/world/WorldGenerator.h>

#include <algorithm>
#include <map>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

world::World shipped(const std::string& category, int seed)
{
	return world::World::load(SRC + "/config/worlds/eval/" + category + "/seed" + std::to_string(seed) + ".ini");
}

/** Smallest gap from an object's footprint to the arena's or an interior wall. */
double wallGap(const world::World& w, const world::Table& t)
{
	double g = INFINITY;
	for (const auto& o : w.obstacles())
		if (o.table < 0) g = std::min(g, t.footprint().gap(o));
	return g;
}

/** The objects per class; each object's length and width within `jitter` of its class's
 *  (exactly its class's when 0). */
std::map<std::string, int> classes(const world::World& w, double jitter = 0, double legJitter = 0, double textureJitter = 0)
{
	std::map<std::string, int> n;
	for (const auto& t : w.tables)
	{
		n[t.object_class.str()]++;
		const auto c = t.object_class.str();
		const double length = c == "desk" ? 1.4 : c == "chair" ? 0.42 : 1.0, width = c == "desk" ? 0.7 : c == "chair" ? 0.42 : 0.6;
		EXPECT_NEAR(t.length, length, jitter + 1e-9) << c;
		EXPECT_NEAR(t.width, width, jitter + 1e-9) << c;
		if (jitter == 0)
		{
			EXPECT_EQ(t.length, length) << c;
		}
		EXPECT_NEAR(t.leg_width, c == "chair" ? 0.03 : 0.05, legJitter + 1e-9) << c;
		EXPECT_NEAR(t.texture, c == "desk" ? 0.6 : c == "chair" ? 0.5 : 0.7, textureJitter + 1e-9) << c;
	}
	return n;
}
}  // namespace

TEST(WorldGeneratorWalls, ShippedWorldsObeyTheirCategory)
{
	const auto robot = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
	for (int seed = 1; seed <= 5; seed++)
	{
		SCOPED_TRACE("seed " + std::to_string(seed));
		const auto walls = shipped("walls", seed), mixed = shipped("mixed_classes", seed), near = shipped("near_walls", seed);
		EXPECT_EQ(walls.walls.size(), 3u);
		EXPECT_EQ(classes(walls), (std::map<std::string, int>{{"table", 6}}));
		for (const auto& t : walls.tables) EXPECT_GE(wallGap(walls, t), 0.15 - 1e-9);
		EXPECT_EQ(mixed.walls.size(), 0u);
		EXPECT_EQ(classes(mixed), (std::map<std::string, int>{{"chair", 4}, {"desk", 2}, {"table", 2}}));
		// sized_classes: mixed_classes's objects at their own sizes, within 3 cm of their class's.
		const auto sized = shipped("sized_classes", seed);
		EXPECT_EQ(classes(sized, 0.03), (std::map<std::string, int>{{"chair", 4}, {"desk", 2}, {"table", 2}}));
		const auto nominal = std::count_if(sized.tables.begin(), sized.tables.end(), [](const world::Table& t) {
			return t.length == 1.0 || t.length == 1.4 || t.length == 0.42;
		});
		EXPECT_LE(nominal, 1);  // a 1 mm grid in +-3 cm: a nominal length is a 1 in 61 chance
		for (const auto& t : sized.tables) EXPECT_EQ(t.leg_width, t.object_class.str() == "chair" ? 0.03 : 0.05);
		// varied_legs: the same, each object with its own leg width (+-1 cm) and texture (+-0.1).
		const auto varied = shipped("varied_legs", seed);
		EXPECT_EQ(classes(varied, 0.03, 0.01, 0.1), (std::map<std::string, int>{{"chair", 4}, {"desk", 2}, {"table", 2}}));
		const auto nominalLegs = std::count_if(varied.tables.begin(), varied.tables.end(), [](const world::Table& t) {
			return t.leg_width == 0.05 || t.leg_width == 0.03;
		});
		EXPECT_LE(nominalLegs, 1);  // a 1 mm grid in +-1 cm: a nominal leg width is a 1 in 21 chance
		EXPECT_EQ(near.walls.size(), 2u);
		EXPECT_EQ(classes(near), (std::map<std::string, int>{{"chair", 3}, {"desk", 2}, {"table", 2}}));
		for (const auto& t : near.tables)
		{
			EXPECT_GE(wallGap(near, t), 0.05 - 1e-9);
			EXPECT_LE(wallGap(near, t), 0.25 + 1e-9);
		}
		for (const auto* w : {&walls, &near})
			for (const auto& v : w->walls)
			{
				EXPECT_EQ(v.thickness, 0.1);
				EXPECT_TRUE(v.x0 == v.x1 || v.y0 == v.y1);  // along x or y
				EXPECT_GE(v.length(), 1.0 - 1e-3);
				EXPECT_LE(v.length(), 2.5 + 1e-3);
			}
		// Every path pose is free (never through a wall) and the path touches every wall.
		for (const auto& [category, w] : {std::pair<std::string, const world::World*>{"walls", &walls}, {"near_walls", &near}})
		{
			const auto path = world::Trajectory::readPathFile(
				SRC + "/config/worlds/eval/" + category + "/seed" + std::to_string(seed) + ".path");
			world::WhiskerSimulator sim(*w, robot, {}, 1);
			std::vector<size_t> touched(w->walls.size(), 0);
			for (const auto& p : path)
			{
				ASSERT_TRUE(sim.poseIsFree(p));
				for (const auto& s : sim.sense(p, mrpt::Clock::fromDouble(1e9))->toShapelets(p))
					for (size_t k = 0; k < w->walls.size(); k++) touched[k] += w->walls[k].slab().distance({s.x, s.y}) < 1e-9;
			}
			for (size_t k = 0; k < touched.size(); k++) EXPECT_GT(touched[k], 0u) << category << " wall " << k;
		}
	}
}

TEST(WorldGeneratorWalls, SameSeedSameWalls)
{
	world::WorldGenerator::TSettings s;
	s.robot = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
	s.noises = {world::NoisePreset::load(SRC + "/config/noise/noiseless.ini")};
	const world::WorldGenerator g(s);
	const auto a = g.generate("near_walls", 11), b = g.generate("near_walls", 11), c = g.generate("near_walls", 12);
	ASSERT_EQ(a.world.walls.size(), 2u);
	ASSERT_EQ(b.world.walls.size(), 2u);
	for (size_t k = 0; k < 2; k++)
	{
		EXPECT_EQ(a.world.walls[k].x0, b.world.walls[k].x0);
		EXPECT_EQ(a.world.walls[k].y1, b.world.walls[k].y1);
	}
	for (size_t i = 0; i < a.world.tables.size(); i++) EXPECT_TRUE(a.world.tables[i].object_class == b.world.tables[i].object_class);
	EXPECT_NE(a.world.walls[0].x0 + a.world.walls[0].y0, c.world.walls[0].x0 + c.world.walls[0].y0);
	EXPECT_EQ(a.description(), b.description());
}
