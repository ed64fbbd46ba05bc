#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/EvalPaths.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>
#include <whiskermap/world/WorldGenerator.h>

#include <algorithm>
#include <filesystem>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
const std::string EVAL = SRC + "/config/worlds/eval/";
world::Robot robot() { return world::Robot::load(SRC + "/config/robots/scratchbot.ini"); }

world::WorldGenerator generator(uint64_t simSeed = 1)
{
	world::WorldGenerator::TSettings s;
	s.robot = robot();
	s.noises = {world::NoisePreset::load(SRC + "/config/noise/noiseless.ini")};
	s.simSeed = simSeed;
	return world::WorldGenerator(s);
}

double closestGap(const world::World& w)
{
	double g = INFINITY;
	for (size_t i = 0; i < w.tables.size(); i++)
		for (size_t j = i + 1; j < w.tables.size(); j++) g = std::min(g, w.tables[i].footprint().gap(w.tables[j].footprint()));
	return g;
}

/** Pairs of tables side by side: two legs of one facing two legs of the other, `lo`-`hi` m apart. */
int sideBySidePairs(const world::World& w, double lo, double hi)
{
	int pairs = 0;
	for (size_t i = 0; i < w.tables.size(); i++)
		for (size_t j = i + 1; j < w.tables.size(); j++)
		{
			int facing = 0;
			for (int a = 0; a < 4; a++)
				for (int b = 0; b < 4; b++)
				{
					const double d = (w.tables[i].legCentre(a) - w.tables[j].legCentre(b)).norm();
					facing += d >= lo && d <= hi;
				}
			pairs += facing == 2;
		}
	return pairs;
}

struct Shipped
{
	world::World world;
	std::vector<mrpt::poses::CPose2D> path;
};
Shipped shipped(const std::string& category, int seed)
{
	const std::string stem = EVAL + category + "/seed" + std::to_string(seed);
	return {world::World::load(stem + ".ini"), world::Trajectory::readPathFile(stem + ".path")};
}
}  // namespace

TEST(Obstacle, GapBetweenSolids)
{
	const auto a = world::Obstacle::rectangle({0, 0}, 0, 0.5, 0.5, 0.7);
	EXPECT_NEAR(a.gap(world::Obstacle::rectangle({1.1, 0}, 0, 0.5, 0.5, 0.7)), 0.1, 1e-12);
	EXPECT_NEAR(a.gap(world::Obstacle::rectangle({1.1, 1.1}, 0, 0.5, 0.5, 0.7)), std::hypot(0.1, 0.1), 1e-12);
	EXPECT_EQ(a.gap(world::Obstacle::rectangle({0.9, 0}, M_PI / 4, 0.5, 0.5, 0.7)), 0.0);  // overlapping
}

TEST(WorldGenerator, SameSeedSameWorldAndPath)
{
	const auto g = generator();
	for (const auto& c : world::WorldGenerator::categories())
	{
		if (c == "large") continue;  // the slowest; covered by the shipped files
		const auto a = g.generate(c, 7), b = g.generate(c, 7), other = g.generate(c, 8);
		ASSERT_EQ(a.world.tables.size(), b.world.tables.size()) << c;
		for (size_t i = 0; i < a.world.tables.size(); i++)
		{
			EXPECT_EQ(a.world.tables[i].x, b.world.tables[i].x) << c;
			EXPECT_EQ(a.world.tables[i].yaw, b.world.tables[i].yaw) << c;
		}
		ASSERT_EQ(a.path.size(), b.path.size()) << c;
		for (size_t i = 0; i < a.path.size(); i++) EXPECT_EQ(a.path[i], b.path[i]) << c;
		EXPECT_NE(a.world.tables[0].x, other.world.tables[0].x) << c;
		EXPECT_EQ(a.description(), b.description());
	}
}

TEST(WorldGenerator, UnknownCategoryIsAnError)
{
	EXPECT_THROW(generator().generate("kitchen", 1), core::Error);
}

TEST(WorldGenerator, ShippedWorldsObeyTheirCategory)
{
	for (int seed = 1; seed <= 5; seed++)
	{
		SCOPED_TRACE("seed " + std::to_string(seed));
		const auto random = shipped("random_yaw", seed), clutter = shipped("clutter", seed);
		const auto side = shipped("side_by_side", seed), large = shipped("large", seed), sparse = shipped("sparse", seed);
		EXPECT_EQ(random.world.tables.size(), 6u);
		EXPECT_EQ(random.world.x_max, 4);
		EXPECT_GE(closestGap(random.world), 0.3);
		EXPECT_EQ(clutter.world.tables.size(), 8u);
		EXPECT_GE(closestGap(clutter.world), 0.15);
		EXPECT_LE(closestGap(clutter.world), 0.25);
		EXPECT_EQ(side.world.tables.size(), 6u);
		EXPECT_EQ(sideBySidePairs(side.world, 0.10, 0.20), 2);
		EXPECT_EQ(large.world.tables.size(), 24u);
		EXPECT_EQ(large.world.x_max, 8);
		EXPECT_EQ(large.world.y_max, 8);
		EXPECT_EQ(sparse.world.tables.size(), 6u);
		for (const auto* s : {&random, &clutter, &side, &large, &sparse})
			for (const auto& t : s->world.tables)
			{
				EXPECT_EQ(t.length, 1.0);
				EXPECT_EQ(t.width, 0.6);
				EXPECT_EQ(t.leg_width, 0.05);
				EXPECT_EQ(t.texture, 0.7);
				EXPECT_EQ(s->world.wall_texture, 0.3);
			}
	}
}

TEST(WorldGenerator, ShippedGridPathsAreThePaperGridWithoutBlockedPoses)
{
	const auto r = robot();
	for (const auto& [category, n] : {std::pair<std::string, int>{"random_yaw", 10}, {"clutter", 10}, {"side_by_side", 10}, {"large", 20}})
		for (int seed = 1; seed <= 5; seed++)
		{
			SCOPED_TRACE(category + " seed " + std::to_string(seed));
			const auto s = shipped(category, seed);
			const world::WhiskerSimulator sim(s.world, r, {}, 1);
			const auto grid = world::Trajectory::paperGrid(s.world, n);
			size_t blocked = 0;
			for (const auto& p : grid) blocked += !sim.poseIsFree(p);
			EXPECT_GT(blocked, 0u);  // the worlds do block some grid poses: they were dropped
			EXPECT_EQ(s.path.size() + blocked, grid.size());
			for (const auto& p : s.path) EXPECT_TRUE(sim.poseIsFree(p));
			EXPECT_TRUE(world::EvalPaths::gridConnected(s.world, r, n));
			const auto audit = world::TouchAudit::run(s.world, r, {}, seed, s.path);
			EXPECT_EQ(audit.identifiable(), s.world.tables.size());
		}
}

TEST(WorldGenerator, ShippedSparsePathsNeverHoldTwoLegsOfATableInSevenContacts)
{
	const auto r = robot();
	for (int seed = 1; seed <= 5; seed++)
		for (const std::string noise : {"noiseless", "default", "very-noisy"})
		{
			SCOPED_TRACE("seed " + std::to_string(seed) + " " + noise);
			const auto s = shipped("sparse", seed);
			const auto audit = world::TouchAudit::run(
				s.world, r, world::NoisePreset::load(SRC + "/config/noise/" + noise + ".ini"), seed, s.path);
			EXPECT_EQ(audit.blockedPoses, 0u);
			EXPECT_GE(audit.closestCrossLegSpacing(), 7u);
			EXPECT_GE(audit.fewestLegs(), 2);  // every table identifiable over the whole run
			EXPECT_EQ(audit.identifiable(), s.world.tables.size());
		}
}

TEST(TouchAudit, AGridPathHoldsTwoLegsOfATableInOneSweep)
{
	// The check can fail: on the paper grid one sweep often touches two legs of a table.
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	const auto audit = world::TouchAudit::run(w, robot(), {}, 1, world::Trajectory::paperGrid(w));
	EXPECT_LT(audit.closestCrossLegSpacing(), 7u);
	EXPECT_EQ(audit.identifiable(), 6u);
	EXPECT_GT(audit.tableContacts(), 0u);
	EXPECT_LT(audit.tableContacts(), audit.contacts.size());  // walls too
}

TEST(Trajectory, WrittenPathFileReadsBackTheSamePoses)
{
	const std::vector<mrpt::poses::CPose2D> poses{{1.234, 0.5, core::deg2rad(-12.3)}, {3, 2, core::deg2rad(90)}};
	const auto p = (std::filesystem::temp_directory_path() / "whiskermap_written.path").string();
	world::Trajectory::writePathFile(p, poses, "two poses\nsecond line");
	const auto back = world::Trajectory::readPathFile(p);
	std::filesystem::remove(p);
	ASSERT_EQ(back.size(), 2u);
	for (size_t i = 0; i < 2; i++) EXPECT_EQ(back[i], poses[i]);
	EXPECT_THROW(world::Trajectory::writePathFile("/dev/null/x.path", poses), core::Error);
}
