#include <gtest/gtest.h>
#include <whiskermap/model/Factors.h>

#include <cmath>

using namespace whiskermap::model;

TEST(Factors, PowersOfEpsilon)
{
	ModelParams p;
	p.epsilon = 0.1;
	const double le = std::log(0.1);
	EXPECT_NEAR(logMissingLegs(3, p), 3 * le, 1e-12);  // eq. 15
	EXPECT_NEAR(logSameCorner(2, p), 2 * le, 1e-12);  // eq. 17
	EXPECT_NEAR(logOverlap(1, p), le, 1e-12);  // eq. 16
	EXPECT_EQ(logOverlap(0, p), 0);
}

TEST(Factors, TableConstraintsCountMissingCornersAndSameCornerPairs)
{
	ModelParams p;
	p.epsilon = 0.1;
	const double le = std::log(0.1);
	EXPECT_NEAR(logTableConstraints({0, 0, 0, 0}, p), 4 * le, 1e-12);
	EXPECT_NEAR(logTableConstraints({1, 1, 1, 1}, p), 0, 1e-12);
	EXPECT_NEAR(logTableConstraints({2, 0, 1, 1}, p), 2 * le, 1e-12);  // 1 missing + 1 pair
	EXPECT_NEAR(logTableConstraints({3, 1, 1, 1}, p), 3 * le, 1e-12);  // 3 pairs at one corner
}
