#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/Ospa.h>

#include <cmath>

using whiskermap::eval::Ospa;
using Points = std::vector<Eigen::Vector2d>;

TEST(Ospa, EmptySets)
{
	EXPECT_EQ(Ospa::distance({}, {}, 0.5, 1), 0.0);
	const Points three{{0, 0}, {1, 1}, {2, 2}};
	EXPECT_EQ(Ospa::distance({}, three, 0.5, 1), 0.5);
	EXPECT_EQ(Ospa::distance(three, {}, 0.7, 2), 0.7);
}

TEST(Ospa, KnownShifts)
{
	const Points X{{0, 0}, {1, 0}}, Y{{1, 0.2}, {0.1, 0}};  // Y listed in the other order
	EXPECT_NEAR(Ospa::distance(X, Y, 0.5, 1), (0.1 + 0.2) / 2, 1e-12);
	EXPECT_NEAR(Ospa::distance(X, Y, 0.5, 2), std::sqrt((0.01 + 0.04) / 2), 1e-12);
	EXPECT_NEAR(Ospa::distance(Y, X, 0.5, 2), std::sqrt((0.01 + 0.04) / 2), 1e-12);  // symmetric
	EXPECT_EQ(Ospa::distance(X, X, 0.5, 1), 0.0);
	// A shift beyond the cut-off costs c.
	EXPECT_NEAR(Ospa::distance({{0, 0}}, {{2, 0}}, 0.5, 1), 0.5, 1e-12);
}

TEST(Ospa, CardinalityErrorCostsC)
{
	// One exact match and one extra point: (0 + c) / 2.
	EXPECT_NEAR(Ospa::distance({{0, 0}}, {{0, 0}, {5, 5}}, 0.5, 1), 0.25, 1e-12);
	EXPECT_NEAR(Ospa::distance({{0, 0}}, {{0, 0}, {5, 5}}, 0.5, 2), std::sqrt(0.25 / 2), 1e-12);
}

TEST(Ospa, RejectsBadParameters)
{
	EXPECT_THROW(Ospa::distance({}, {}, 0, 1), whiskermap::core::Error);
	EXPECT_THROW(Ospa::distance({}, {}, 0.5, 0.5), whiskermap::core::Error);
}
