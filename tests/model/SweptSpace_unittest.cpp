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

// A segment's deepest point in a sector. The vertical line x = 0.5 crosses the quadrant for
// 0 <= y < 0.866; its depth there is min(1 - hypot(0.5, y), y, 0.5), largest where
// y = 1 - hypot(0.5, y): y = 0.375.
TEST(SweptSpace, SegmentPenetrationByHand)
{
	EXPECT_NEAR(SweptSpace::segmentPenetration(QUADRANT, 0.5, -1, 0.5, 2), 0.375, 1e-9);
	EXPECT_NEAR(SweptSpace::segmentPenetration(QUADRANT, 0.5, 2, 0.5, -1), 0.375, 1e-9);  // either direction
	// Cut short at y = 0.1 it is deepest at its end, by that end's distance to the +x ray.
	EXPECT_NEAR(SweptSpace::segmentPenetration(QUADRANT, 0.5, -1, 0.5, 0.1), 0.1, 1e-9);
	EXPECT_EQ(SweptSpace::segmentPenetration(QUADRANT, -0.1, -1, -0.1, 2), 0);  // beside it
	EXPECT_EQ(SweptSpace::segmentPenetration(QUADRANT, 0.8, 0.8, 2, 0.8), 0);  // beyond its reach
	EXPECT_EQ(SweptSpace::segmentPenetration(QUADRANT, 0.2, 0, 0.9, 0), 0);  // along its ray
}

// Against a dense scan of the same depth along random segments and sectors (spans up to
// 180 degrees, where the golden section is exact, and wider ones, where 64 samples bound it
// from below).
TEST(SweptSpace, SegmentPenetrationMatchesADenseScan)
{
	uint64_t state = 12345;
	const auto uniform = [&] {
		state = state * 6364136223846793005ull + 1442695040888963407ull;
		return static_cast<double>(state >> 11) / 9007199254740992.0;
	};
	int deep = 0;
	for (int i = 0; i < 800; i++)
	{
		const SweptSector s{0, 0, 0.6, 2 * M_PI * uniform(), (i % 4 == 3 ? 2 : 1) * M_PI * uniform()};
		const double ax = 1.6 * uniform() - 0.8, ay = 1.6 * uniform() - 0.8, bx = 1.6 * uniform() - 0.8,
					 by = 1.6 * uniform() - 0.8;
		double scan = 0;
		for (int k = 0; k <= 20000; k++)
			scan = std::max(scan, s.depth(ax + (bx - ax) * k / 20000.0, ay + (by - ay) * k / 20000.0));
		const double d = SweptSpace::segmentPenetration(s, ax, ay, bx, by);
		if (s.span <= M_PI)
		{
			EXPECT_NEAR(d, scan, 1e-4) << i;  // the scan's step is under 0.1 mm
			EXPECT_GE(d, scan - 1e-7) << i;  // the golden section stops within 1e-8 of the optimum
		}
		else
			EXPECT_LE(d, scan + 1e-12) << i;  // a lower bound
		deep += d > 0.01;
	}
	EXPECT_GT(deep, 120);  // the scan met many segments deep inside
}

// eq. 21 for a wall: a slab across the swept quadrant pays per sector by its deepest point; a
// wall beyond the whisker's reach, or one the whisker stopped against, pays nothing.
TEST(SweptSpace, WallFactorByHand)
{
	const model::ModelParams p = freeSpaceOn();
	SweptSpace space;
	space.assign({QUADRANT});
	// Across the quadrant along x = 0.5, 10 cm thick: its left face (x = 0.45) reaches 0.45 -
	// deeper than the centre line (0.375) and the right face: min(1 - hypot(0.45, y), y, 0.45)
	// is largest at y = 0.3986, where it is 0.3986 metres, far beyond sigma_r: log p_miss.
	model::Wall across{0.5, -1, 0.5, 2, 0.1, 0.3};
	EXPECT_NEAR(space.logWallFactor(across, p), std::log(p.free_space_p_miss), 1e-9);
	// 1 cm into the sector past the +x ray: d = 1 cm, log(0.05 + 0.95 e^-1).
	const model::Wall grazing{0.2, -0.04, 0.8, -0.04, 0.1, 0.3};
	EXPECT_NEAR(space.logWallFactor(grazing, p), std::log(0.05 + 0.95 * std::exp(-1.0)), 1e-9);
	EXPECT_EQ(space.logWallFactor({0.2, -0.06, 0.8, -0.06, 0.1, 0.3}, p), 0);  // the face on the ray: outside
	EXPECT_EQ(space.logWallFactor({2, -1, 2, 2, 0.1, 0.3}, p), 0);  // beyond the reach
	EXPECT_EQ(space.logWallFactor(across, model::ModelParams()), 0);  // free space off
	EXPECT_EQ(SweptSpace().logWallFactor(across, p), 0);  // no sectors (the lasting map)
}
