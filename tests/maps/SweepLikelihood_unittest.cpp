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
