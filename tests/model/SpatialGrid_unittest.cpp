#include <gtest/gtest.h>
#include <whiskermap/model/SpatialGrid.h>

#include <algorithm>
#include <vector>

using whiskermap::model::Id;
using whiskermap::model::SpatialGrid;

namespace
{
std::vector<Id> near(const SpatialGrid& g, double x, double y, double r)
{
	std::vector<Id> out;
	g.forEachNear(x, y, r, [&](Id id) { out.push_back(id); });
	std::sort(out.begin(), out.end());
	return out;
}
}  // namespace

TEST(SpatialGrid, FindsPointsInTheCellsAroundAndForgetsErased)
{
	SpatialGrid g(0.5);
	g.insert(1, 0.1, 0.1);
	g.insert(2, 0.3, 0.2);  // same cell
	g.insert(3, 2.2, 2.2);
	EXPECT_EQ(near(g, 0.2, 0.2, 0.1), (std::vector<Id>{1, 2}));
	EXPECT_EQ(near(g, 2.0, 2.0, 0.6), (std::vector<Id>{3}));
	EXPECT_EQ(near(g, 1.2, 1.2, 0.1), (std::vector<Id>{}));
	g.erase(1, 0.1, 0.1);
	g.erase(7, 0.1, 0.1);  // not there: nothing happens
	EXPECT_EQ(near(g, 0.2, 0.2, 0.1), (std::vector<Id>{2}));
	g.erase(2, 0.3, 0.2);  // the cell empties, and stays
	EXPECT_EQ(near(g, 0.2, 0.2, 0.1), (std::vector<Id>{}));
	g.insert(4, 0.4, 0.4);
	EXPECT_EQ(near(g, 0.2, 0.2, 0.1), (std::vector<Id>{4}));
	g.clear();
	EXPECT_EQ(near(g, 2.0, 2.0, 0.6), (std::vector<Id>{}));
	EXPECT_EQ(g.chunkCount(), 0u);
}

TEST(SpatialGrid, CopiesShareCellsUntilOneWrites)
{
	SpatialGrid a(0.5);
	for (Id i = 0; i < 100; i++) a.insert(i, 0.5 * (i % 10), 0.5 * (i / 10));  // 100 cells
	const size_t chunks = a.chunkCount();
	EXPECT_GT(chunks, 1u);
	SpatialGrid b = a;
	EXPECT_EQ(b.sharedChunks(), chunks);
	b.insert(100, 0.1, 0.1);  // into an open cell: one chunk of cells duplicated, the hash map still shared
	EXPECT_EQ(b.sharedChunks(), chunks - 1);
	b.erase(99, 4.5, 4.5);
	EXPECT_EQ(b.sharedChunks(), chunks - 2);
	b.insert(101, -3, -3);  // a new cell: b's own hash map
	EXPECT_LT(b.sharedChunks(), chunks - 2);
	EXPECT_EQ(near(a, 0.1, 0.1, 0.1), (std::vector<Id>{0}));
	EXPECT_EQ(near(b, 0.1, 0.1, 0.1), (std::vector<Id>{0, 100}));
	EXPECT_EQ(near(a, 4.6, 4.6, 0.1), (std::vector<Id>{99}));
	EXPECT_EQ(near(b, 4.6, 4.6, 0.1), (std::vector<Id>{}));
	EXPECT_EQ(near(a, -2.9, -2.9, 0.1), (std::vector<Id>{}));
	EXPECT_EQ(near(b, -2.9, -2.9, 0.1), (std::vector<Id>{101}));
}
