#include <gtest/gtest.h>
#include <whiskermap/model/Blackboard.h>
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
