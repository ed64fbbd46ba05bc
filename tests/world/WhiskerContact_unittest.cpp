#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/world/WhiskerContact.h>

#include <cmath>

using namespace whiskermap::world;
using whiskermap::core::deg2rad;

namespace
{
const Eigen::Vector2d O(0, 0);
/** A 10 cm square leg centred at (cx, cy). */
std::vector<Obstacle> leg(double cx, double cy)
{
	return {Obstacle::rectangle({cx, cy}, 0, 0.05, 0.05, 0.7, 0, 0)};
}
/** A long slab whose left face is the line x = xFace, far beyond reach in y. */
std::vector<Obstacle> slab(double xFace)
{
	return {Obstacle::rectangle({xFace + 0.15, 0}, 0, 0.15, 5.0, 0.3)};
}
}  // namespace

TEST(WhiskerContact, FixedWhiskerHitsNearestFace)
{
	const auto c = WhiskerContact::first(O, 1.0, 0, 0, leg(0.5, 0));
	ASSERT_TRUE(c);
	EXPECT_NEAR(c->r, 0.45, 1e-12);
	EXPECT_NEAR(c->point.x(), 0.45, 1e-12);
	EXPECT_NEAR(std::abs(c->normal), M_PI, 1e-12);  // the face looking back at the pivot
	EXPECT_EQ(c->obstacle, 0);
}

TEST(WhiskerContact, MissesWhatIsOutOfReachOrOutOfTheSweep)
{
	EXPECT_FALSE(WhiskerContact::first(O, 0.44, 0, 0, leg(0.5, 0)));  // too short
	EXPECT_FALSE(WhiskerContact::first(O, 1.0, deg2rad(20), deg2rad(90), leg(0.5, 0)));  // sweep misses
	EXPECT_FALSE(WhiskerContact::first(O, 1.0, deg2rad(-90), deg2rad(-20), leg(0.5, 0)));
}

TEST(WhiskerContact, SweepingShaftMeetsTheFirstCornerAndReportsTheFaceItPressesOn)
{
	// Counter-clockwise from -90 deg: the first thing the shaft meets is the corner
	// (0.45, -0.05); it moves upward there, so it presses on the bottom face (normal -y).
	const auto c = WhiskerContact::first(O, 1.0, deg2rad(-90), deg2rad(90), leg(0.5, 0));
	ASSERT_TRUE(c);
	EXPECT_NEAR(c->angle, std::atan2(-0.05, 0.45), 1e-12);
	EXPECT_NEAR(c->r, std::hypot(0.45, 0.05), 1e-12);
	EXPECT_NEAR(c->normal, -M_PI / 2, 1e-12);
	// Clockwise from +90 deg: mirror image, corner (0.45, 0.05), top face (normal +y).
	const auto d = WhiskerContact::first(O, 1.0, deg2rad(90), deg2rad(-90), leg(0.5, 0));
	ASSERT_TRUE(d);
	EXPECT_NEAR(d->angle, std::atan2(0.05, 0.45), 1e-12);
	EXPECT_NEAR(d->normal, M_PI / 2, 1e-12);
}

TEST(WhiskerContact, TipMeetsAFaceWhenNoCornerIsInReach)
{
	// Face at x = 0.45, tip radius 0.5: the tip first touches it at y = -sqrt(0.5^2 - 0.45^2).
	const auto c = WhiskerContact::first(O, 0.5, deg2rad(-90), deg2rad(90), slab(0.45));
	ASSERT_TRUE(c);
	const double y = -std::sqrt(0.25 - 0.2025);
	EXPECT_NEAR(c->point.x(), 0.45, 1e-12);
	EXPECT_NEAR(c->point.y(), y, 1e-12);
	EXPECT_NEAR(c->r, 0.5, 1e-12);
	EXPECT_NEAR(c->angle, std::atan2(y, 0.45), 1e-12);
	EXPECT_NEAR(std::abs(c->normal), M_PI, 1e-12);
}

TEST(WhiskerContact, GrazingTipCountsAsATouch)
{
	// The tip circle is tangent to the face x = 0.5: one touching point, straight ahead.
	const auto c = WhiskerContact::first(O, 0.5, deg2rad(-90), deg2rad(90), slab(0.5));
	ASSERT_TRUE(c);
	EXPECT_NEAR(c->angle, 0, 1e-6);
	EXPECT_NEAR(c->point.y(), 0, 1e-6);
	// A hair shorter and it misses.
	EXPECT_FALSE(WhiskerContact::first(O, 0.5 - 1e-9, deg2rad(-90), deg2rad(90), slab(0.5)));
}

TEST(WhiskerContact, ShaftAlreadyAcrossAnObstacleTouchesAtTheStart)
{
	const auto c = WhiskerContact::first(O, 1.0, 0, deg2rad(90), leg(0.5, 0));
	ASSERT_TRUE(c);
	EXPECT_NEAR(c->angle, 0, 1e-12);
	EXPECT_NEAR(c->r, 0.45, 1e-12);
}

TEST(WhiskerContact, NearestOfSeveralObstaclesWins)
{
	auto obs = leg(0.8, 0);
	obs.push_back(leg(0.4, 0)[0]);
	const auto c = WhiskerContact::first(O, 1.0, 0, 0, obs);
	ASSERT_TRUE(c);
	EXPECT_EQ(c->obstacle, 1);
	EXPECT_NEAR(c->r, 0.35, 1e-12);
}

TEST(Obstacle, DistanceIsZeroInsideAndEuclideanOutside)
{
	const auto o = leg(0, 0)[0];
	EXPECT_EQ(o.distance({0.01, -0.02}), 0);  // inside the leg
	EXPECT_NEAR(o.distance({0.15, 0}), 0.10, 1e-12);  // off a face
	EXPECT_NEAR(o.distance({0.08, 0.09}), std::hypot(0.03, 0.04), 1e-12);  // off a corner
}

TEST(Obstacle, IntersectsBySeparatingAxes)
{
	const auto a = Obstacle::rectangle({0, 0}, 0, 0.5, 0.5, 0);
	EXPECT_TRUE(a.intersects(Obstacle::rectangle({0.9, 0}, 0, 0.5, 0.5, 0)));
	EXPECT_FALSE(a.intersects(Obstacle::rectangle({1.1, 0}, 0, 0.5, 0.5, 0)));
	// Rotated 45 deg: its corner reaches 0.707 from its centre.
	EXPECT_TRUE(a.intersects(Obstacle::rectangle({1.15, 0}, M_PI / 4, 0.5, 0.5, 0)));
	EXPECT_FALSE(a.intersects(Obstacle::rectangle({1.25, 0}, M_PI / 4, 0.5, 0.5, 0)));
}
