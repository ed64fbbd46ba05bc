#include <gtest/gtest.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/SweptSpace.h>

#include <cmath>

using namespace whiskermap;
using model::OrientedRect;
using model::SweptSpace;
using obs::SweptSector;

namespace
{
// A whisker of 1 m pivoting at the origin that swept the first quadrant.
const SweptSector QUADRANT{0, 0, 1, 0, M_PI / 2};

model::ModelParams freeSpaceOn()
{
	model::ModelParams p;
	p.free_space = true;  // sigma_r 0.01, p_miss 0.05
	return p;
}
}  // namespace

// Distance to the nearest piece of the boundary: a ray, the arc, or the pivot for a ray more
// than 90 degrees away; 0 outside.
TEST(SweptSpace, SectorDepthByHand)
{
	EXPECT_NEAR(QUADRANT.depth(0.5, 0.2), 0.2, 1e-12);  // the ray along +x
	EXPECT_NEAR(QUADRANT.depth(0.2, 0.5), 0.2, 1e-12);  // the ray along +y
	EXPECT_NEAR(QUADRANT.depth(0.7, 0.7), 1 - std::sqrt(0.98), 1e-12);  // the arc
	EXPECT_EQ(QUADRANT.depth(-0.1, 0.5), 0);  // beside it
	EXPECT_EQ(QUADRANT.depth(0.8, 0.8), 0);  // beyond the shaft's reach
	const SweptSector wide{0, 0, 1, 0, 1.5 * M_PI};  // three quadrants
	EXPECT_NEAR(wide.depth(-0.6, 0.3), 1 - std::hypot(0.6, 0.3), 1e-12);  // both rays > 90 deg away
	EXPECT_NEAR(wide.depth(-0.3, 0.01), std::hypot(0.3, 0.01), 1e-12);  // ... the pivot is nearer than the arc
}

// How far a leg reaches into a sector: its deepest point.
TEST(SweptSpace, PenetrationByHand)
{
	// A 5 cm square leg 1 cm below the +x ray pokes 1.5 cm into the sector.
	EXPECT_NEAR(SweptSpace::penetration(QUADRANT, {0.5, -0.01, 0, 0.025, 0.025}), 0.015, 1e-12);
	// Turned 45 degrees, its corner reaches half a diagonal above its centre.
	EXPECT_NEAR(
		SweptSpace::penetration(QUADRANT, {0.5, -0.02, M_PI / 4, 0.025, 0.025}), 0.025 * std::sqrt(2.0) - 0.02, 1e-12);
	EXPECT_EQ(SweptSpace::penetration(QUADRANT, {0.5, -0.1, 0, 0.025, 0.025}), 0);  // outside
	// Against the arc: the corner nearest the pivot is the deepest point.
	EXPECT_NEAR(
		SweptSpace::penetration(QUADRANT, {0.7, 0.7, 0, 0.025, 0.025}), 1 - std::hypot(0.675, 0.675), 1e-12);
}

// eq. 21: log(p_miss + (1 - p_miss) exp(-d^2 / sigma_r^2)) per sector.
TEST(SweptSpace, FactorByHand)
{
	model::ModelParams p = freeSpaceOn();
	SweptSpace space;
	space.assign({QUADRANT});
	const OrientedRect poking{0.5, -0.01, 0, 0.025, 0.025};  // d = 1.5 cm = 1.5 sigma_r
	EXPECT_NEAR(space.logFactor(poking, p), -1.8962586004255464, 1e-12);  // log(0.05 + 0.95 e^-2.25)
	EXPECT_EQ(space.logFactor({0.5, -0.1, 0, 0.025, 0.025}, p), 0);  // outside: no cost
	p.free_space_p_miss = 0.2;
	p.sigma_r = 0.02;
	EXPECT_NEAR(space.logFactor(poking, p), -0.42185937300556225, 1e-12);  // log(0.2 + 0.8 e^-0.5625)
	space.assign({QUADRANT, QUADRANT});  // two whiskers: two chances to touch
	EXPECT_NEAR(space.logFactor(poking, p), 2 * -0.42185937300556225, 1e-12);
	p.free_space = false;  // the paper's model
	EXPECT_EQ(space.logFactor(poking, p), 0);
}

// A table's empty corner counts as the leg it implies there; a corner with a leg does not.
TEST(SweptSpace, EmptyCornersByHand)
{
	const model::ModelParams p = freeSpaceOn();
	SweptSpace space;
	space.assign({QUADRANT});
	// Corner 0 (+,+) at (0.4, 0.3), its leg 0.325 m deep; the other three corners outside.
	const model::Table t{-0.1, 0, 0, p.leg_width, p.texture};
	const double deep = std::log(p.free_space_p_miss + (1 - p.free_space_p_miss) * std::exp(-std::pow(0.325 / 0.01, 2)));
	EXPECT_NEAR(space.logEmptyCorners(t, {0, 0, 0, 0}, p), deep, 1e-12);
	EXPECT_NEAR(deep, std::log(0.05), 1e-12);
	EXPECT_EQ(space.logEmptyCorners(t, {1, 0, 0, 0}, p), 0);
	EXPECT_EQ(space.logEmptyCorners(t, {0, 0, 0, 0}, model::ModelParams()), 0);  // off
}
