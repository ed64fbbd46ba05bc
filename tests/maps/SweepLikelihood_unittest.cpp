#include <gtest/gtest.h>
#include <whiskermap/maps/SweepLikelihood.h>
#include <whiskermap/world/WhiskerSimulator.h>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

/** One table in a large arena; the map holds exactly its legs. */
struct OneTable : ::testing::Test
{
	world::World w;
	std::vector<world::Obstacle> legs;
	world::Robot robot = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
	void SetUp() override
	{
		w.x_min = w.y_min = 0;
		w.x_max = w.y_max = 10;
		w.tables.push_back(world::Table{5, 5, 0.3, 1.0, 0.6, 0.05, 0.7});
		for (int k = 0; k < 4; k++) legs.push_back(w.tables[0].leg(k, 0));
	}
	double ll(const obs::CObservationWhiskerContacts& o, const mrpt::poses::CPose2D& p) const
	{
		return maps::SweepLikelihood::logLikelihood(o, p, legs, {});
	}
};
}  // namespace

TEST_F(OneTable, PeaksAtTheTruePose)
{
	world::WhiskerSimulator sim(w, robot, {}, 1);
	const mrpt::poses::CPose2D truth(5.0, 5.0, 0.3);  // under the table
	const auto o = sim.sense(truth, mrpt::Clock::fromDouble(1e9));
	ASSERT_GE(o->contactCount(), 4u);
	const double best = ll(*o, truth);
	EXPECT_NEAR(best, 0, 1e-9);  // every contact exactly where predicted
	for (double dx : {-0.1, -0.05, 0.05, 0.1})
		for (double dth : {-0.2, 0.0, 0.2})
			EXPECT_LT(ll(*o, truth + mrpt::poses::CPose2D(dx, dx / 2, dth)), best);
}

TEST_F(OneTable, UntouchedWhiskersWhereTheMapPredictsContactArePenalised)
{
	world::World empty = w;
	empty.tables.clear();
	world::WhiskerSimulator sim(empty, robot, {}, 1);
	const mrpt::poses::CPose2D p(5.0, 5.0, 0.3);
	const auto o = sim.sense(p, mrpt::Clock::fromDouble(1e9));  // touches nothing
	ASSERT_EQ(o->contactCount(), 0u);
	const maps::SweepLikelihood::TOptions opts;
	// Under the mapped table every whisker should touch a leg: each miss costs log(p_miss).
	EXPECT_NEAR(ll(*o, p), o->whiskers.size() * std::log(opts.p_miss), 1e-9);
	// Far from the table, the map predicts nothing either: no penalty.
	EXPECT_EQ(ll(*o, mrpt::poses::CPose2D(1, 1, 0)), 0.0);
}

// ---------------------------------------------------------------- with the map's swept grid

namespace
{
maps::SweepLikelihood::TOptions withGrid()
{
	maps::SweepLikelihood::TOptions o;
	o.use_swept_grid = true;
	return o;
}

/** The grid a mapping run leaves: sweeps of `world` at the poses of a 0.3 m lattice over
 *  [x0, x1] x [y0, y1], four headings each. */
whiskermap::model::SweptGrid sweptOver(
	const world::World& world, const world::Robot& robot, double x0, double x1, double y0, double y1)
{
	world::WhiskerSimulator sim(world, robot, {}, 1);
	whiskermap::model::SweptGrid g(0.1);
	for (double x = x0; x <= x1 + 1e-9; x += 0.3)
		for (double y = y0; y <= y1 + 1e-9; y += 0.3)
			for (double yaw : {0.0, M_PI / 2, M_PI, -M_PI / 2})
			{
				const mrpt::poses::CPose2D p(x, y, yaw);
				const auto o = sim.sense(p, mrpt::Clock::fromDouble(1e9));
				std::vector<std::array<double, 2>> contacts;
				for (const auto& s : o->toShapelets(p)) contacts.push_back({s.x, s.y});
				g.addSweep(x, y, o->toSweptSectors(p), contacts);
			}
	return g;
}
}  // namespace

TEST_F(OneTable, WithoutAGridOrWithItsFreeSpaceOffTheLikelihoodIsUnchanged)
{
	world::WhiskerSimulator sim(w, robot, {}, 1);
	const mrpt::poses::CPose2D truth(5.0, 5.0, 0.3);
	const auto o = sim.sense(truth, mrpt::Clock::fromDouble(1e9));
	const auto grid = sweptOver(w, robot, 4, 6, 4, 6);
	const maps::SweepLikelihood::TOptions off;  // the default: no grid
	const whiskermap::model::SweptGrid empty;
	for (const auto& p : {truth, mrpt::poses::CPose2D(5.1, 4.9, 0.5), mrpt::poses::CPose2D(1, 1, 0)})
	{
		EXPECT_EQ(maps::SweepLikelihood::logLikelihood(*o, p, legs, off, &grid), ll(*o, p));
		EXPECT_EQ(maps::SweepLikelihood::logLikelihood(*o, p, legs, withGrid(), &empty), ll(*o, p));
	}
}

// A map that knows no legs, only where it swept and touched: the contacts alone pull the
// likelihood to the truth (contacts in swept free space are unlikely), which the legacy
// likelihood cannot (every unexplained contact costs log(p_unexplained) wherever it lands).
TEST_F(OneTable, ContactsInSweptFreeSpaceAreUnlikely)
{
	world::WhiskerSimulator sim(w, robot, {}, 1);
	const mrpt::poses::CPose2D truth(5.0, 5.0, 0.3);
	const auto o = sim.sense(truth, mrpt::Clock::fromDouble(1e9));
	ASSERT_GE(o->contactCount(), 4u);
	const auto grid = sweptOver(w, robot, 3.5, 6.5, 3.5, 6.5);
	const auto opts = withGrid();
	const double atTruth = maps::SweepLikelihood::logLikelihood(*o, truth, {}, opts, &grid);
	for (double dx : {-0.3, -0.2, 0.2, 0.3})
		for (double dth : {-0.3, 0.0, 0.3})
		{
			const auto p = truth + mrpt::poses::CPose2D(dx, -dx / 2, dth);
			EXPECT_EQ(  // legacy: the same at every pose
				maps::SweepLikelihood::logLikelihood(*o, p, {}, opts), maps::SweepLikelihood::logLikelihood(*o, truth, {}, opts));
			EXPECT_LT(maps::SweepLikelihood::logLikelihood(*o, p, {}, opts, &grid), atTruth - 1) << dx << " " << dth;
		}
	// A contact in a swept, never touched cell costs more than one in unexplored space.
	const auto freeCell = grid.at(4.05, 4.05), unexplored = grid.at(8.05, 8.05);
	ASSERT_GT(freeCell.passes, 3);
	ASSERT_EQ(freeCell.touches, 0);
	ASSERT_FALSE(unexplored.explored());
	EXPECT_LT(maps::SweepLikelihood::touchChance(freeCell, opts), opts.cell_prior / 3);
	EXPECT_EQ(maps::SweepLikelihood::touchChance(unexplored, opts), opts.cell_prior);
}

// The map knows where it ends: a pose, and whiskers, outside the explored area pay
// log(p_unexplored) each (eqs. L4, L5), where the legacy likelihood sees an empty world.
TEST_F(OneTable, PosesWhereTheMapNeverExploredArePenalised)
{
	world::World empty = w;
	empty.tables.clear();
	world::WhiskerSimulator sim(empty, robot, {}, 1);
	const mrpt::poses::CPose2D inside(2.0, 2.0, 0.0), outside(8.5, 8.5, 0.0);
	const auto o = sim.sense(inside, mrpt::Clock::fromDouble(1e9));
	ASSERT_EQ(o->contactCount(), 0u);
	const auto grid = sweptOver(empty, robot, 1, 3, 1, 3);
	const auto opts = withGrid();
	EXPECT_EQ(ll(*o, inside), ll(*o, outside));
	const double in = maps::SweepLikelihood::logLikelihood(*o, inside, {}, opts, &grid);
	const double out = maps::SweepLikelihood::logLikelihood(*o, outside, {}, opts, &grid);
	// Out there: the robot's cell and every whisker's boundary unexplored.
	EXPECT_NEAR(out, (1 + o->whiskers.size()) * std::log(opts.p_unexplored), 1e-9);
	EXPECT_GT(in, 0);  // swept free space where nothing was touched: a small reward
}
