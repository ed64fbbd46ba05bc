#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/ExactMapOracle.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Posterior.h>

#include <cstdio>
#include <stdexcept>

#include "SyntheticTable.h"

using namespace whiskermap;
using inference::ExactMapOracle;
using inference::OracleResult;
using model::ModelParams;
using model::Table;
using test::touchTable;

namespace
{
const ModelParams P;
// Off the 1 cm / 1 degree grid on purpose.
const Table truth{1.3037, -0.4021, 0.5042, P.leg_width, P.texture};
/** Below any structural change (the smallest, an invented vs a missing leg, is 1.7 nats);
 *  above the grid's effect on a 3-leg table (doc/oracle.md). */
constexpr double GRID_TOLERANCE = 1.0;

/** logJoint of a HypothesisSet over `shapelets`, rebuilt on a fresh blackboard. */
double logJointOf(const model::HypothesisSet& h, const std::vector<obs::Shapelet>& shapelets)
{
	model::Blackboard bb(P);
	bb.reset(shapelets);
	for (const Table& t : h.tables) bb.addTable(t);
	for (const model::Leg& l : h.legs) bb.addLeg(l);
	for (size_t s = 0; s < shapelets.size(); s++) bb.setShapeletParent(s, h.shapeletParent[s]);
	return model::logJoint(bb);
}

/** The true configuration: `t`, a leg exactly at each corner, each shapelet on its leg. */
model::HypothesisSet trueConfiguration(const Table& t, const std::vector<test::Touch>& touches)
{
	model::HypothesisSet h;
	h.tables.push_back(t);
	for (int c = 0; c < 4; c++)
	{
		model::Leg l;
		model::tableCorner(t, c, P, l.x, l.y);
		l.theta = t.theta;
		l.wx = l.wy = t.leg_width;
		l.texture = t.texture;
		l.parent = 0;
		h.legs.push_back(l);
	}
	for (const test::Touch& touch : touches) h.shapeletParent.push_back(touch.corner);
	return h;
}

double cornerError(const Table& a, const Table& b)
{
	double worst = 0;
	for (int i = 0; i < 4; i++)
	{
		double ax = 0, ay = 0, best = 1e9;
		model::tableCorner(a, i, P, ax, ay);
		for (int j = 0; j < 4; j++)
		{
			double bx = 0, by = 0;
			model::tableCorner(b, j, P, bx, by);
			best = std::min(best, std::hypot(ax - bx, ay - by));
		}
		worst = std::max(worst, best);
	}
	return worst;
}
}  // namespace

TEST(ExactMapOracle, NoShapeletsGiveAnEmptyMap)
{
	const OracleResult r = ExactMapOracle(P).solve({});
	EXPECT_TRUE(r.map.tables.empty());
	EXPECT_TRUE(r.map.legs.empty());
	EXPECT_EQ(r.logPosterior, 0);  // logJoint of an empty board
	EXPECT_TRUE(r.certified);
}

TEST(ExactMapOracle, OneContactGetsAFreeLegOnItsFace)
{
	const auto shapelets = touchTable(truth, P, {{2, 1, 0.0}});
	const OracleResult r = ExactMapOracle(P).solve(shapelets);
	ASSERT_TRUE(r.map.tables.empty());
	ASSERT_EQ(r.map.legs.size(), 1u);
	EXPECT_EQ(r.map.shapeletParent[0], 0);
	// Perfect fit: cell of an uncaused leg plus a perfectly explained contact (eqs. 7-9, 19).
	const double expected = model::logCell(model::logLegNull(P), P) + model::logNoisyOr(std::log(P.alpha_S), model::logShapeletNull(P));
	EXPECT_NEAR(r.logPosterior, expected, 1e-6);
	EXPECT_NEAR(r.logPosterior, logJointOf(r.map, shapelets), 1e-9);
}

TEST(ExactMapOracle, ThreeTouchedLegsGiveTheTableWithinGridResolution)
{
	const std::vector<test::Touch> touches{{0, 0, 0.01}, {1, 1, -0.01}, {2, 3, 0.0}, {2, 2, 0.015}};
	const auto shapelets = touchTable(truth, P, touches);
	const OracleResult r = ExactMapOracle(P).solve(shapelets);
	ASSERT_EQ(r.map.tables.size(), 1u);
	const Table& t = r.map.tables[0];
	EXPECT_LT(std::hypot(t.x - truth.x, t.y - truth.y), 0.01);
	EXPECT_LT(std::abs(core::angleDiff(t.theta, truth.theta, M_PI)), core::deg2rad(1));
	EXPECT_LT(cornerError(t, truth), 0.01);
	EXPECT_EQ(r.map.legs.size(), 4u);  // three touched, one invented
	const double exact = logJointOf(trueConfiguration(truth, touches), shapelets);
	EXPECT_GE(r.logPosterior, exact - GRID_TOLERANCE);
	EXPECT_NEAR(r.logPosterior, logJointOf(r.map, shapelets), 1e-9);
	EXPECT_TRUE(r.certified);
	EXPECT_GT(r.configurationsScored, 1000u);
}

// The 2 cm / 2 deg grid is a subset of the 1 cm / 1 deg one: exact over each grid, the finer
// optimum can only be higher. Both approach the off-grid truth.
TEST(ExactMapOracle, NestedGridsGiveNestedOptima)
{
	const std::vector<test::Touch> touches{{0, 0, 0.01}, {1, 1, -0.01}, {2, 3, 0.0}};
	const auto shapelets = touchTable(truth, P, touches);
	inference::OracleOptions coarse;
	coarse.grid_step = 0.02;
	coarse.yaw_step = core::deg2rad(2);
	const double fine = ExactMapOracle(P).solve(shapelets).logPosterior;
	const double rough = ExactMapOracle(P, coarse).solve(shapelets).logPosterior;
	const double exact = logJointOf(trueConfiguration(truth, touches), shapelets);
	std::printf("3 touched legs: truth %.3f, oracle 1 cm/1 deg %.3f, 2 cm/2 deg %.3f\n", exact, fine, rough);
	EXPECT_GE(fine, rough - 1e-9);
	EXPECT_GE(fine, exact - GRID_TOLERANCE);
}

// Two legs on one side: the table and its mirror image tie (paper's "ambiguous poses").
TEST(ExactMapOracle, TwoTouchedLegsGiveTheTableOrItsMirror)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {0, 1, -0.01}, {1, 1, 0.0}, {1, 2, 0.02}});
	const OracleResult r = ExactMapOracle(P).solve(shapelets);
	ASSERT_EQ(r.map.tables.size(), 1u);
	Table mirror = truth;
	double c1x = 0, c1y = 0, c2x = 0, c2y = 0;
	model::tableCorner(truth, 1, P, c1x, c1y);
	model::tableCorner(truth, 2, P, c2x, c2y);
	mirror.x += c1x - c2x, mirror.y += c1y - c2y;
	EXPECT_LT(std::min(cornerError(r.map.tables[0], truth), cornerError(r.map.tables[0], mirror)), 0.01);
}

TEST(ExactMapOracle, TwoTablesWhenBothAreTouched)
{
	const Table other{-0.9046, 1.1083, 2.2, P.leg_width, P.texture};
	auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {1, 1, -0.01}, {2, 3, 0.0}});
	for (const auto& s : touchTable(other, P, {{3, 0, 0.0}, {2, 3, 0.01}, {1, 2, -0.01}})) shapelets.push_back(s);
	const OracleResult r = ExactMapOracle(P).solve(shapelets);
	ASSERT_EQ(r.map.tables.size(), 2u);
	const double e0 = std::min(cornerError(r.map.tables[0], truth), cornerError(r.map.tables[0], other));
	const double e1 = std::min(cornerError(r.map.tables[1], truth), cornerError(r.map.tables[1], other));
	EXPECT_LT(std::max(e0, e1), 0.01);
	EXPECT_NEAR(r.logPosterior, logJointOf(r.map, shapelets), 1e-9);

	inference::OracleOptions one;
	one.max_tables = 1;
	EXPECT_LT(ExactMapOracle(P, one).solve(shapelets).logPosterior, r.logPosterior - 10);
}

TEST(ExactMapOracle, RejectsWhatItCannotSolve)
{
	ModelParams generous = P;
	generous.c_T = 1e6;  // a table with one touched leg would pay off: pruning argument fails
	EXPECT_THROW(ExactMapOracle{generous}, std::invalid_argument);
	inference::OracleOptions o;
	o.max_tables = 3;
	EXPECT_THROW(ExactMapOracle(P, o), std::invalid_argument);
	EXPECT_THROW(ExactMapOracle(P).solve(std::vector<obs::Shapelet>(9)), std::invalid_argument);
}
