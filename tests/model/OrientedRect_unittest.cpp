#include <gtest/gtest.h>
#include <whiskermap/model/OrientedRect.h>

#include <cmath>
#include <random>

using whiskermap::model::OrientedRect;

namespace
{
const OrientedRect square{0, 0, 0, 0.05, 0.05};  // 10 cm square at the origin
}

TEST(OrientedRect, DistanceOutsideAnEdge)
{
	const auto h = square.perimeter(0.07, 0.01);
	EXPECT_NEAR(h.distance, 0.02, 1e-12);
	EXPECT_NEAR(h.faceNormal, 0, 1e-12);
	const auto w = square.perimeter(-0.07, 0.0);
	EXPECT_NEAR(w.distance, 0.02, 1e-12);
	EXPECT_NEAR(std::abs(w.faceNormal), M_PI, 1e-12);
	EXPECT_NEAR(square.perimeter(0.0, -0.09).faceNormal, -M_PI_2, 1e-12);
}

TEST(OrientedRect, DistanceInsideIsToTheNearestFace)
{
	const auto h = square.perimeter(0.03, -0.01);  // 2 cm from +x face, 4 cm from -y face
	EXPECT_NEAR(h.distance, 0.02, 1e-12);
	EXPECT_NEAR(h.faceNormal, 0, 1e-12);
	const auto v = square.perimeter(0.01, -0.045);  // 0.5 cm from -y face
	EXPECT_NEAR(v.distance, 0.005, 1e-12);
	EXPECT_NEAR(v.faceNormal, -M_PI_2, 1e-12);
	EXPECT_NEAR(square.perimeter(0, 0).distance, 0.05, 1e-12);
}

TEST(OrientedRect, DistanceBeyondACornerIsToTheCorner)
{
	const auto h = square.perimeter(0.08, 0.09);  // corner (0.05, 0.05): offsets 3, 4 cm
	EXPECT_NEAR(h.distance, 0.05, 1e-12);
	EXPECT_NEAR(h.faceNormal, M_PI_2, 1e-12);  // deeper out of the y slab
}

TEST(OrientedRect, OnThePerimeterIsZero)
{
	EXPECT_NEAR(square.perimeter(0.05, 0.02).distance, 0, 1e-12);
	EXPECT_NEAR(square.perimeter(0.05, 0.05).distance, 0, 1e-12);
}

TEST(OrientedRect, RotatedRectangle)
{
	// 45 degrees, half-extents 0.1 x 0.02, centre (1, 2): its +x face normal points along 45 deg.
	const OrientedRect r{1, 2, M_PI_4, 0.1, 0.02};
	const double c = std::cos(M_PI_4), s = std::sin(M_PI_4);
	const auto h = r.perimeter(1 + 0.15 * c, 2 + 0.15 * s);
	EXPECT_NEAR(h.distance, 0.05, 1e-12);
	EXPECT_NEAR(h.faceNormal, M_PI_4, 1e-12);
	// Along the rotated local y axis, 3 cm out: the +y face, normal 135 deg.
	const auto v = r.perimeter(1 - 0.05 * s, 2 + 0.05 * c);
	EXPECT_NEAR(v.distance, 0.03, 1e-12);
	EXPECT_NEAR(v.faceNormal, 3 * M_PI_4, 1e-12);
}

TEST(OrientedRect, Overlaps)
{
	EXPECT_TRUE(square.overlaps({0.09, 0, 0, 0.05, 0.05}));
	EXPECT_FALSE(square.overlaps({0.11, 0, 0, 0.05, 0.05}));
	EXPECT_FALSE(square.overlaps({0.10, 0, 0, 0.05, 0.05}));  // touching is not overlapping
	// Diagonal neighbour: axis-aligned boxes would overlap, the rotated one does not.
	EXPECT_TRUE(square.overlaps({0.09, 0.09, 0, 0.05, 0.05}));
	EXPECT_FALSE(square.overlaps({0.115, 0.115, M_PI_4, 0.05, 0.05}));
	EXPECT_TRUE(square.overlaps({0.08, 0.08, M_PI_4, 0.05, 0.05}));  // its edge x + y = 0.089
	// A long thin bar crossing the square with no corner inside it.
	EXPECT_TRUE(square.overlaps({0, 0, M_PI_2, 1.0, 0.01}));
}

TEST(OrientedRect, FartherThanRejectsOnlyPointsBeyondTheDistance)
{
	// The cheap reject may only say "farther" for points whose exact perimeter distance exceeds
	// d, and must say it for most points well outside the circumcircle (else it saves nothing).
	std::mt19937_64 rng(7);
	std::uniform_real_distribution<double> u(-1, 1);
	int rejected = 0, far = 0;
	for (int i = 0; i < 20000; i++)
	{
		const OrientedRect r{u(rng), u(rng), 4 * u(rng), 0.01 + 0.2 * std::abs(u(rng)), 0.01 + 0.2 * std::abs(u(rng))};
		const double x = r.cx + u(rng), y = r.cy + u(rng), d = 0.3 * std::abs(u(rng));
		const double exact = r.perimeter(x, y).distance;
		if (r.fartherThan(x, y, d))
		{
			EXPECT_GT(exact, d) << i;
			rejected++;
		}
		far += std::hypot(x - r.cx, y - r.cy) > 1.01 * (d + std::hypot(r.hx, r.hy));
	}
	EXPECT_GE(rejected, far);
	EXPECT_GT(far, 5000);
	// On the circumcircle at distance d exactly: not rejected.
	EXPECT_FALSE(square.fartherThan(0.05 + 0.1 / std::sqrt(2.0), 0.05 + 0.1 / std::sqrt(2.0), 0.1));
}
