#include <gtest/gtest.h>
#include <whiskermap/model/SpatialHash.h>

#include <algorithm>
#include <vector>

using namespace whiskermap::model;

namespace
{
std::vector<Id> near(const SpatialHash& h, double x, double y, double r)
{
	std::vector<Id> out;
	h.forEachNear(x, y, r, [&](Id id) { out.push_back(id); });
	return out;
}
}  // namespace

// Regression (issue 8): 32-bit cells overflowed near x = 2^31 cells, and the query loop
// (ix <= INT32_MAX; ix++) never ended.
TEST(SpatialHash, AnyFiniteCoordinateIsFoundAndQueriesEnd)
{
	SpatialHash h(1.0, 16);
	const double far[] = {2147483647.5, -2147483648.5, 4.3e9, 1e15, -1e15, 1e300, -1e300};
	for (size_t i = 0; i < std::size(far); i++)
	{
		h.clear();
		h.insert(static_cast<Id>(i), far[i], -far[i]);
		EXPECT_EQ(near(h, far[i], -far[i], 0.6), std::vector<Id>{static_cast<Id>(i)}) << far[i];
		EXPECT_TRUE(near(h, 0, 0, 0.6).empty());
		h.erase(static_cast<Id>(i), far[i], -far[i]);
		EXPECT_TRUE(near(h, far[i], -far[i], 0.6).empty());
	}
}

TEST(SpatialHash, NearbyPointsInNeighbouringCellsAreFound)
{
	SpatialHash h(0.5);
	h.insert(1, -0.01, 0.0);
	h.insert(2, 0.01, 0.0);
	h.insert(3, 3.0, 3.0);
	auto ids = near(h, 0, 0, 0.1);
	std::sort(ids.begin(), ids.end());
	EXPECT_EQ(ids, (std::vector<Id>{1, 2}));
}
