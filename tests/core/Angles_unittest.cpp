#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>

#include <cmath>

using namespace whiskermap::core;

TEST(Angles, WrapToPi)
{
	EXPECT_NEAR(wrapToPi(3 * M_PI / 2), -M_PI / 2, 1e-12);
	EXPECT_NEAR(wrapToPi(-3 * M_PI / 2), M_PI / 2, 1e-12);
	EXPECT_NEAR(wrapToPi(M_PI), M_PI, 1e-12);  // (-pi, pi]
	EXPECT_NEAR(wrapToPi(-M_PI), M_PI, 1e-12);
	EXPECT_NEAR(wrapToPi(0.3), 0.3, 1e-12);
}

TEST(Angles, DifferenceModuloSymmetry)
{
	// A rectangle (period pi): 179 deg and -1 deg are the same orientation.
	EXPECT_NEAR(angleDiff(deg2rad(179), deg2rad(-1), M_PI), 0, 1e-12);
	// A square (period pi/2): 80 deg vs -5 deg differ by -5 deg.
	EXPECT_NEAR(rad2deg(angleDiff(deg2rad(80), deg2rad(-5), M_PI / 2)), -5, 1e-9);
	EXPECT_NEAR(rad2deg(angleDiff(deg2rad(10), deg2rad(350), 2 * M_PI)), 20, 1e-9);
}
