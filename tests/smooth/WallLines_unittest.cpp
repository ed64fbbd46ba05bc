#include <gtest/gtest.h>
#include <whiskermap/smooth/WallLines.h>

using namespace whiskermap;

namespace
{
/** A wall piece along y at x, from y0 to y1, 10 cm thick. */
world::Obstacle alongY(double x, double y0, double y1)
{
	return world::Obstacle::rectangle({x, (y0 + y1) / 2}, M_PI / 2, (y1 - y0) / 2, 0.05, 0.5);
}

double centreX(const world::Obstacle& o) { return (o.corners[0].x() + o.corners[2].x()) / 2; }
}  // namespace

TEST(WallLines, PiecesOfOneStraightWallBecomeOne)
{
	std::vector<world::Obstacle> solids = {
		alongY(0.00, 0, 1),  // 1 m
		world::Obstacle::rectangle({1, 1}, 0.3, 0.025, 0.025, 0.5, 0, 0),  // a leg: never moved
		alongY(0.06, 1.2, 1.7),  // 0.5 m, 6 cm off the first: the same wall
		alongY(0.50, 0, 1),  // parallel but 0.5 m away: another wall
		world::Obstacle::rectangle({2, 0.03}, 0, 1, 0.05, 0.5),  // at right angles: another wall
	};
	const auto leg = solids[1];
	std::vector<size_t> groups = {0, 1, 2, 3, 4};
	const size_t count = smooth::WallLines::merge(solids, groups, 0.1);
	EXPECT_EQ(count, 4u);
	EXPECT_EQ(groups, (std::vector<size_t>{0, 1, 0, 2, 3}));
	// Both pieces on the length-weighted mean line: (1 x 0 + 0.5 x 0.06) / 1.5 = 0.02.
	EXPECT_NEAR(centreX(solids[0]), 0.02, 1e-12);
	EXPECT_NEAR(centreX(solids[2]), 0.02, 1e-12);
	EXPECT_NEAR(solids[2].corners[0].y() + solids[2].corners[2].y(), 2.9, 1e-12);  // not moved along
	EXPECT_NEAR(centreX(solids[3]), 0.5, 1e-12);
	EXPECT_EQ(solids[1].corners, leg.corners);
	// A distance of 0: nothing merges.
	std::vector<size_t> alone = {0, 1, 2, 3, 4};
	auto again = solids;
	again[2] = alongY(0.06, 1.2, 1.7);
	EXPECT_EQ(smooth::WallLines::merge(again, alone, 0.01), 5u);
}
