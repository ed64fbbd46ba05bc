#include <gtest/gtest.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/GridFreeSpace.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>

using namespace whiskermap::model;

namespace
{
/** A grid of 0.1 m cells around a wall along y = 0.05 from x = 0.05 to 0.35 (cells (0..3, 0)):
 *  (0, 0) swept twice, never touched; (1, 0) swept 4 times, never touched; (2, 0) swept 3
 *  times and touched once; (3, 0) never explored; (1, 1), off the wall, swept 9 times. */
SweptGrid gridAlongTheWall()
{
	SweptGrid g(0.1);
	g.set(0, 0, {2, 0});
	g.set(1, 0, {4, 0});
	g.set(2, 0, {3, 1});
	g.set(1, 1, {9, 0});
	return g;
}

Wall theWall()
{
	Wall w;
	w.x0 = 0.05, w.y0 = 0.05, w.x1 = 0.35, w.y1 = 0.05;
	w.thickness = 0.1, w.texture = 0.3;
	return w;
}
}  // namespace

TEST(GridFreeSpace, EachPassOfAnUntouchedCellOnTheCentreLineCosts)
{
	ModelParams p;
	p.free_space_p_miss = 0.05;
	// eq. 25 by hand: cells (0, 0) and (1, 0) are swept and untouched, 2 + 4 passes at
	// log((1 + 0.05) / 2) = -0.6444 nats each; (2, 0) was touched, (3, 0) never explored,
	// (1, 1) is off the centre line.
	EXPECT_NEAR(GridFreeSpace::logWallFactor(theWall(), gridAlongTheWall(), p), 6 * std::log(0.525), 1e-12);
	EXPECT_NEAR(6 * std::log(0.525), -3.8662, 1e-4);
	// p_miss = 1: a whisker always misses, so free space says nothing.
	p.free_space_p_miss = 1;
	EXPECT_DOUBLE_EQ(GridFreeSpace::logWallFactor(theWall(), gridAlongTheWall(), p), 0);
	// A wall of zero length is one cell: (0, 0).
	p.free_space_p_miss = 0.05;
	Wall point = theWall();
	point.x1 = point.x0;
	EXPECT_NEAR(GridFreeSpace::logWallFactor(point, gridAlongTheWall(), p), 2 * std::log(0.525), 1e-12);
	// Reversed end points cross the same cells.
	Wall reversed = theWall();
	std::swap(reversed.x0, reversed.x1);
	EXPECT_NEAR(GridFreeSpace::logWallFactor(reversed, gridAlongTheWall(), p), 6 * std::log(0.525), 1e-12);
}

TEST(GridFreeSpace, WallLogOddsAndTheJointCarryItOnlyWithFreeSpaceAndAGrid)
{
	const SweptGrid grid = gridAlongTheWall();
	for (const bool freeSpace : {false, true})
	{
		ModelParams p;
		p.walls = true;
		p.free_space = freeSpace;
		Blackboard bb(p);
		bb.reset({});
		const Id w = bb.addWall(theWall());
		const double oddsWithout = logOddsWall(bb, w), jointWithout = logJoint(bb);
		bb.setSweptGrid(&grid);
		const double expected = freeSpace ? GridFreeSpace::logWallFactor(theWall(), grid, p) : 0;
		EXPECT_NEAR(logOddsWall(bb, w) - oddsWithout, expected, 1e-9) << "free_space " << freeSpace;
		EXPECT_NEAR(logJoint(bb) - jointWithout, expected, 1e-9) << "free_space " << freeSpace;
		bb.reset({});  // the grid is the map's, not the problem's: a reset keeps it
		EXPECT_EQ(bb.sweptGrid(), &grid);
	}
}

TEST(GridFreeSpace, ALegWhereNothingWasEverTouchedPaysPerPassOfItsCell)
{
	ModelParams p;  // sigma_r 0.01: a 5 cm leg's neighbourhood reaches 0.045 m from its centre
	p.free_space_p_miss = 0.05;
	SweptGrid g(0.1);
	g.set(5, 5, {6, 0});  // the cell of (0.55, 0.55): swept 6 times, never touched
	// eq. 27 by hand: h = 0.05 / (2 x 0.1) = 0.25; per pass log(1 - 0.95 x 0.25) = -0.2712.
	EXPECT_NEAR(GridFreeSpace::logLegFactor(0.55, 0.55, 0.05, g, p), 6 * std::log(1 - 0.95 * 0.25), 1e-12);
	EXPECT_NEAR(6 * std::log(0.7625), -1.6269, 1e-4);
	// A 3 cm chair leg: h = 0.15, per pass log(1 - 0.95 x 0.15).
	EXPECT_NEAR(GridFreeSpace::logLegFactor(0.55, 0.55, 0.03, g, p), 6 * std::log(1 - 0.95 * 0.15), 1e-12);
	// A touch where the leg's own contacts would fall (within 0.045 m: cell (6, 5) from x =
	// 0.6) says the cell is not empty: nothing. A touch farther away (cell (7, 5)) does not.
	SweptGrid near = g, far = g;
	near.set(6, 5, {0, 1});
	far.set(7, 5, {0, 1});
	EXPECT_EQ(GridFreeSpace::logLegFactor(0.57, 0.55, 0.05, near, p), 0.0);  // 0.57 + 0.045 reaches 0.615
	EXPECT_NEAR(GridFreeSpace::logLegFactor(0.57, 0.55, 0.05, far, p), 6 * std::log(0.7625), 1e-12);
	// Never passed, or touched in its own cell: nothing.
	EXPECT_EQ(GridFreeSpace::logLegFactor(0.25, 0.55, 0.05, g, p), 0.0);
	g.set(5, 5, {6, 2});
	EXPECT_EQ(GridFreeSpace::logLegFactor(0.55, 0.55, 0.05, g, p), 0.0);
}

TEST(GridFreeSpace, LegsAndEmptyCornersCarryItInTheJointAndTheirLogOdds)
{
	// A 1.0 x 0.6 table at (1, 1) with one leg at corner 0 (1.5, 1.3); the grid swept every
	// corner's cell 4 times, never touched. With free space and the grid, the leg pays eq. 27
	// in its log-odds and the joint, the three empty corners in the table's log-odds and the joint.
	SweptGrid grid(0.1);
	ModelParams base;
	base.free_space_p_miss = 0.05;
	Table t{1, 1, 0, 0.05, 0.7};
	double cx[4], cy[4];
	tableCorners(t, base, cx, cy);
	for (int k = 0; k < 4; k++) grid.set(grid.index(cx[k]), grid.index(cy[k]), {4, 0});
	const double perCorner = GridFreeSpace::logLegFactor(cx[0], cy[0], 0.05, grid, base);
	ASSERT_NEAR(perCorner, 4 * std::log(0.7625), 1e-12);
	for (const bool freeSpace : {false, true})
	{
		ModelParams p = base;
		p.free_space = freeSpace;
		Blackboard bb(p);
		bb.reset({});
		const Id table = bb.addTable(t);
		Leg l;
		l.x = cx[0], l.y = cy[0], l.theta = 0, l.wx = l.wy = 0.05, l.texture = 0.7, l.parent = table;
		const Id leg = bb.addLeg(l);
		const double joint = logJoint(bb), legOdds = logOddsLeg(bb, leg), tableOdds = logOddsTable(bb, table);
		const double gain = logLegLinkGain(bb, leg, table);
		bb.setSweptGrid(&grid);
		const double on = freeSpace ? 1 : 0;
		EXPECT_NEAR(logJoint(bb) - joint, on * 4 * perCorner, 1e-9) << freeSpace;  // the leg and 3 empty corners
		EXPECT_NEAR(logOddsTable(bb, table) - tableOdds, on * 3 * perCorner, 1e-9) << freeSpace;
		// The leg's own factor (perCorner) and its link gain's change (it fills an empty corner
		// that would pay perCorner) cancel: standing where a leg is implied anyway costs nothing more.
		EXPECT_NEAR(logOddsLeg(bb, leg) - legOdds, 0, 1e-9) << freeSpace;
		EXPECT_NEAR(logLegLinkGain(bb, leg, table) - gain, -on * perCorner, 1e-9) << freeSpace;
	}
}

TEST(GridFreeSpace, AWallOfAnyLengthIsScoredInBoundedTime)
{
	// Eq. 25 samples the centre line at most 16,384 times: a quarter cell apart up to 409.6 m
	// (0.1 m cells). A 1,000 m wall along a row of swept, untouched cells (samples 6.1 cm
	// apart) still visits each of its 10,001 cells once; a 3,000 m one (samples 18.3 cm apart,
	// each in a cell of its own) pays for 16,385 of its 30,001 cells: bounded, a lower bound.
	ModelParams p;
	p.free_space_p_miss = 0.05;
	SweptGrid g(0.1);
	for (int32_t ix = 0; ix <= 30000; ix++) g.set(ix, 0, {1, 0});
	Wall w;
	w.x0 = 0.05, w.y0 = 0.05, w.y1 = 0.05, w.thickness = 0.1;
	w.x1 = 1000.05;
	EXPECT_NEAR(GridFreeSpace::logWallFactor(w, g, p), 10001 * std::log(0.525), 1e-6);
	w.x1 = 3000.05;
	EXPECT_NEAR(GridFreeSpace::logWallFactor(w, g, p), 16385 * std::log(0.525), 1e-6);
}
