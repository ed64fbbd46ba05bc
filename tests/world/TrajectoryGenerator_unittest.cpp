// Continuous trajectories (whisker-sim --trajectory lawnmower|explore|wall-follow|loop) and the
// planner they drive with.
#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/PathPlanner.h>
#include <whiskermap/world/TrajectoryGenerator.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>

using namespace whiskermap;
using Kind = world::TrajectorySpec::Kind;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
world::World paperArena() { return world::World::load(SRC + "/config/worlds/paper_arena.ini"); }
world::World randomYaw() { return world::World::load(SRC + "/config/worlds/eval/random_yaw/seed1.ini"); }
world::Robot robot() { return world::Robot::load(SRC + "/config/robots/scratchbot.ini"); }

world::TrajectorySpec spec(Kind kind)
{
	world::TrajectorySpec s;
	s.kind = kind;
	return s;
}

/** Every pose free with room to spare, steps within speed/rate and turn_rate/rate. */
void expectContinuousAndFree(const world::World& w, const std::vector<mrpt::poses::CPose2D>& poses,
	const world::TrajectorySpec& s, const std::string& what)
{
	const auto r = robot();
	const world::WhiskerSimulator sim(w, r, {}, 1);
	const auto obstacles = w.obstacles();
	double closest = INFINITY, maxStep = 0, maxTurn = 0;
	for (size_t i = 0; i < poses.size(); i++)
	{
		EXPECT_TRUE(sim.poseIsFree(poses[i])) << what << " pose " << i;
		for (const auto& o : obstacles) closest = std::min(closest, o.distance({poses[i].x(), poses[i].y()}));
		if (i == 0) continue;
		maxStep = std::max(maxStep, std::hypot(poses[i].x() - poses[i - 1].x(), poses[i].y() - poses[i - 1].y()));
		maxTurn = std::max(maxTurn, std::abs(core::wrapToPi(poses[i].phi() - poses[i - 1].phi())));
	}
	EXPECT_GT(closest, r.radius + 0.01) << what;  // the planner's clearance (2 cm, less a quarter cell)
	EXPECT_LE(maxStep, s.speed / s.rate + 1e-9) << what;
	EXPECT_GT(maxStep, 0.9 * s.speed / s.rate) << what;
	EXPECT_LE(maxTurn, core::deg2rad(s.turn_rate_deg) / s.rate + 1e-9) << what;
}

/** Fraction of the arena (5 cm cells) within whisker reach (0.6 m) of some pose. */
double coverage(const world::World& w, const std::vector<mrpt::poses::CPose2D>& poses)
{
	size_t near = 0, all = 0;
	for (double x = w.x_min + 0.025; x < w.x_max; x += 0.05)
		for (double y = w.y_min + 0.025; y < w.y_max; y += 0.05, all++)
			for (const auto& p : poses)
				if (std::hypot(p.x() - x, p.y() - y) < 0.6)
				{
					near++;
					break;
				}
	return double(near) / all;
}
}  // namespace

TEST(TrajectoryGenerator, EveryKindIsFreeAndContinuousInBothWorlds)
{
	for (const auto& w : {paperArena(), randomYaw()})
		for (Kind k : {Kind::Lawnmower, Kind::Explore, Kind::WallFollow, Kind::Loop})
		{
			const auto s = spec(k);
			const auto poses = world::TrajectoryGenerator::generate(w, robot(), s, 1);
			ASSERT_GT(poses.size(), 100u);
			expectContinuousAndFree(w, poses, s, "kind " + std::to_string(int(k)));
		}
}

TEST(TrajectoryGenerator, EveryKindDrivesRoundTheOfficesInteriorWalls)
{
	// Issue 11: interior walls are obstacles of the planner; steps of at most speed / rate
	// (5 cm) with the body 1 cm clear of every wall never cross a 10 cm wall.
	const auto w = world::World::load(SRC + "/config/worlds/office.ini");
	ASSERT_EQ(w.walls.size(), 2u);
	for (Kind k : {Kind::Lawnmower, Kind::Explore, Kind::WallFollow, Kind::Loop})
	{
		const auto s = spec(k);
		const auto poses = world::TrajectoryGenerator::generate(w, robot(), s, 1);
		ASSERT_GT(poses.size(), 100u);
		expectContinuousAndFree(w, poses, s, "office kind " + std::to_string(int(k)));
	}
	EXPECT_GT(coverage(w, world::TrajectoryGenerator::generate(w, robot(), spec(Kind::Lawnmower), 1)), 0.9);
}

TEST(TrajectoryGenerator, LegsOnALawnmowerRowAreDrivenRound)
{
	// In random_yaw/seed1 some rows run straight through legs: the planner must leave them.
	const auto w = randomYaw();
	const world::PathPlanner planner(w, robot().radius);
	const auto s = spec(Kind::Lawnmower);
	int blockedRows = 0;
	for (double y = 0.25; y < 4; y += s.spacing) blockedRows += !planner.segmentFree({0.25, y}, {3.75, y});
	EXPECT_GT(blockedRows, 0);
	const auto poses = world::TrajectoryGenerator::generate(w, robot(), s, 1);
	expectContinuousAndFree(w, poses, s, "lawnmower");
	EXPECT_GT(coverage(w, poses), 0.97);
}

TEST(TrajectoryGenerator, LawnmowerCoversThePaperArenaInRows)
{
	const auto w = paperArena();
	const auto s = spec(Kind::Lawnmower);
	const auto poses = world::TrajectoryGenerator::generate(w, robot(), s, 1);
	EXPECT_GT(coverage(w, poses), 0.97);
	EXPECT_NEAR(poses.front().x(), 0.25, 1e-12);
	EXPECT_NEAR(poses.front().y(), 0.25, 1e-12);
	EXPECT_NEAR(poses.back().y(), 3.75, 0.05);  // 8 rows, 0.25 .. 3.75
	// 8 rows of 3.5 m and 7 moves of 0.5 m between rows (plus detours): >= 31.5 m at 5 cm.
	EXPECT_GT(poses.size(), 630u);
	EXPECT_LT(poses.size(), 950u);  // with the in-place turns at row ends and round legs
}

TEST(TrajectoryGenerator, LoopEndsAtItsStartPose)
{
	for (uint64_t seed : {1, 2, 3})
	{
		const auto poses = world::TrajectoryGenerator::generate(randomYaw(), robot(), spec(Kind::Loop), seed);
		EXPECT_NEAR(poses.back().x(), poses.front().x(), 1e-9);
		EXPECT_NEAR(poses.back().y(), poses.front().y(), 1e-9);
		EXPECT_NEAR(core::wrapToPi(poses.back().phi() - poses.front().phi()), 0, 1e-9);
		double farthest = 0;
		for (const auto& p : poses) farthest = std::max(farthest, std::hypot(p.x() - poses[0].x(), p.y() - poses[0].y()));
		EXPECT_GT(farthest, 1.0);  // a real excursion, not a turn on the spot
	}
}

TEST(TrajectoryGenerator, WallFollowKeepsItsStandoff)
{
	const auto w = paperArena();
	auto s = spec(Kind::WallFollow);
	const auto poses = world::TrajectoryGenerator::generate(w, robot(), s, 1);
	size_t atStandoff = 0;
	for (const auto& p : poses)
	{
		const double wall = std::min({p.x() - w.x_min, w.x_max - p.x(), p.y() - w.y_min, w.y_max - p.y()});
		atStandoff += std::abs(wall - s.standoff) < 0.01;
	}
	EXPECT_GT(double(atStandoff) / poses.size(), 0.6);  // the rest: round tables near the walls
	EXPECT_NEAR(std::hypot(poses.back().x() - poses[0].x(), poses.back().y() - poses[0].y()), 0, 1e-9);
}

TEST(TrajectoryGenerator, SeededAndLimitedByDurationOrLength)
{
	const auto w = paperArena();
	auto s = spec(Kind::Explore);
	const auto a = world::TrajectoryGenerator::generate(w, robot(), s, 5);
	const auto b = world::TrajectoryGenerator::generate(w, robot(), s, 5);
	const auto c = world::TrajectoryGenerator::generate(w, robot(), s, 6);
	ASSERT_EQ(a.size(), b.size());
	for (size_t i = 0; i < a.size(); i++) EXPECT_EQ(a[i], b[i]);
	EXPECT_EQ(a.size(), 120u * 8 + 1);  // explore's default: 120 s at 8 Hz
	EXPECT_NE(a.back(), c.back());
	expectContinuousAndFree(w, a, s, "explore");
	EXPECT_GT(coverage(w, a), 0.8);

	s.kind = Kind::Lawnmower;
	s.duration = 200;  // longer than one pass: back along the rows
	s.rate = 4;
	s.speed = 0.2;
	const auto longer = world::TrajectoryGenerator::generate(w, robot(), s, 1);
	EXPECT_EQ(longer.size(), 801u);
	expectContinuousAndFree(w, longer, s, "lawnmower 200 s");
	s.duration = 0;
	s.length = 5;
	const auto shortRun = world::TrajectoryGenerator::generate(w, robot(), s, 1);
	double travelled = 0;
	for (size_t i = 1; i < shortRun.size(); i++)
		travelled += std::hypot(shortRun[i].x() - shortRun[i - 1].x(), shortRun[i].y() - shortRun[i - 1].y());
	EXPECT_GE(travelled, 5 - 1e-9);
	EXPECT_LT(travelled, 5 + s.speed / s.rate);
}

TEST(TrajectoryGenerator, BadSpecsAreErrors)
{
	auto s = spec(Kind::Lawnmower);
	s.speed = 0;
	EXPECT_THROW(world::TrajectoryGenerator::generate(paperArena(), robot(), s, 1), core::Error);
	EXPECT_THROW(world::TrajectorySpec::parseKind("spiral"), core::Error);
	EXPECT_EQ(world::TrajectorySpec::parseKind("wall-follow"), Kind::WallFollow);
}

TEST(PathPlanner, RoutesRoundALegAndNeverThroughIt)
{
	world::World w;
	w.x_max = w.y_max = 2;
	world::Table t;
	t.x = 1, t.y = 1, t.length = 1.0, t.width = 0.6, t.leg_width = 0.05, t.texture = 0.7;
	w.tables.push_back(t);
	const world::PathPlanner planner(w, 0.1);
	const Eigen::Vector2d a(0.3, 1.3), b(1.7, 1.3);  // the straight way passes leg 0 and 1's row
	EXPECT_FALSE(planner.segmentFree(a, b));
	const auto way = planner.route(a, b);
	ASSERT_GT(way.size(), 2u);
	EXPECT_EQ(way.front(), a);
	EXPECT_EQ(way.back(), b);
	for (size_t i = 1; i < way.size(); i++) EXPECT_TRUE(planner.segmentFree(way[i - 1], way[i]));
	double length = 0;
	for (size_t i = 1; i < way.size(); i++) length += (way[i] - way[i - 1]).norm();
	EXPECT_LT(length, 1.4 + 0.3);  // a short detour, not round the whole table
	// A place inside a leg is moved to the nearest reachable one.
	const auto leg = t.legCentre(0);
	const auto moved = planner.reachable(leg);
	EXPECT_TRUE(planner.free(moved));
	EXPECT_LT((moved - leg).norm(), 0.2);
}
