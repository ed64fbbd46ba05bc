#include <gtest/gtest.h>
#include <whiskermap/smooth/DuplicateWalls.h>

using namespace whiskermap;
using smooth::DuplicateWalls;

namespace
{
/** A 10 cm thick wall piece along y (east wall), its west face at x, from y0 to y1. */
world::Obstacle eastWall(double x, double y0, double y1)
{
	return world::Obstacle::rectangle({x + 0.05, (y0 + y1) / 2}, M_PI / 2, (y1 - y0) / 2, 0.05, 0.3);
}
const Eigen::Vector2d WEST(-1, 0), EAST(1, 0);
}  // namespace

TEST(DuplicateWalls, AWallMappedTwiceFromOneSideIsOneWall)
{
	// The east wall mapped at x = 4.28 on a first visit and at x = 4.0 later, overlapping
	// along, both touched on their west faces: one wall, held across only.
	const std::vector<world::Obstacle> solids = {eastWall(4.28, 0.2, 1.2), eastWall(4.0, 0.6, 3.8)};
	const std::vector<size_t> groupOf = {0, 1};
	const auto pairs = DuplicateWalls::find(solids, groupOf, {3 * WEST, 5 * WEST}, 0.3);
	ASSERT_EQ(pairs.size(), 1u);
	EXPECT_EQ(pairs[0].a, 0u);
	EXPECT_EQ(pairs[0].b, 1u);
	EXPECT_NEAR(std::abs(pairs[0].normal.x()), 1, 1e-9);
	EXPECT_NEAR(std::abs(pairs[0].normal.dot(pairs[0].offset)), 0.28, 1e-9);
	// Farther apart across than the distance, or not overlapping along: two walls.
	EXPECT_TRUE(DuplicateWalls::find(solids, groupOf, {3 * WEST, 5 * WEST}, 0.25).empty());
	const std::vector<world::Obstacle> apart = {eastWall(4.28, 0.2, 0.5), eastWall(4.0, 0.6, 3.8)};
	EXPECT_TRUE(DuplicateWalls::find(apart, groupOf, {3 * WEST, 5 * WEST}, 0.3).empty());
}

TEST(DuplicateWalls, TheTwoFacesOfAPartitionAreTwoWalls)
{
	// Touched from opposite sides (a thin partition seen from both), untouched, or touched only
	// at an end: nothing pairs. A table's legs (table >= 0) are never read.
	const std::vector<world::Obstacle> solids = {eastWall(2.0, 0, 2), eastWall(2.2, 0, 2)};
	const std::vector<size_t> groupOf = {0, 1};
	EXPECT_TRUE(DuplicateWalls::find(solids, groupOf, {3 * EAST, 5 * WEST}, 0.3).empty());
	EXPECT_TRUE(DuplicateWalls::find(solids, groupOf, {Eigen::Vector2d::Zero(), 5 * WEST}, 0.3).empty());
	EXPECT_TRUE(DuplicateWalls::find(solids, groupOf, {Eigen::Vector2d(0, 3), 5 * WEST}, 0.3).empty());
	auto legs = solids;
	legs[0].table = 0, legs[0].leg = 0;
	EXPECT_TRUE(DuplicateWalls::find(legs, groupOf, {3 * WEST, 5 * WEST}, 0.3).empty());
}
