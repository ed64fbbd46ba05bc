#include <gtest/gtest.h>
#include <whiskermap/model/SweptGrid.h>

#include <cmath>

using whiskermap::model::SweptGrid;
using whiskermap::obs::SweptSector;

namespace
{
/** A quarter disc of radius 0.6 m pivoting at (1, 1), from 0 to 90 degrees. */
const SweptSector QUARTER{1, 1, 0.6, 0, M_PI / 2};
}  // namespace

TEST(SweptGrid, CountsPassesInsideTheSectorOnlyAndTouchesInstead)
{
	SweptGrid g(0.1);
	EXPECT_TRUE(g.empty());
	g.addSweep(0.55, 0.55, {QUARTER}, {{1.35, 1.05}});
	EXPECT_FALSE(g.empty());
	EXPECT_EQ(g.at(1.25, 1.25).passes, 1);  // inside the quarter disc
	EXPECT_EQ(g.at(1.05, 1.55).passes, 1);  // near the arc
	EXPECT_FALSE(g.at(0.85, 1.25).explored());  // behind the pivot, outside the sector
	EXPECT_FALSE(g.at(1.65, 1.65).explored());  // beyond the arc
	EXPECT_EQ(g.at(0.55, 0.55).passes, 1);  // the robot's own cell
	const auto touched = g.at(1.35, 1.05);  // the contact's cell: a touch, not a pass
	EXPECT_EQ(touched.touches, 1);
	EXPECT_EQ(touched.passes, 0);
	g.addSweep(0.55, 0.55, {QUARTER, QUARTER}, {});  // one sweep counts a cell once
	EXPECT_EQ(g.at(1.25, 1.25).passes, 2);
	EXPECT_EQ(g.at(1.35, 1.05).passes, 1);
	EXPECT_EQ(g.at(1.35, 1.05).touches, 1);
}

TEST(SweptGrid, MemoryIsBoundedByTheAreaNotBySweeps)
{
	SweptGrid g(0.1);
	g.addSweep(1, 1, {QUARTER}, {});
	const size_t chunks = g.chunkCount(), cells = g.cells().size();
	for (int k = 0; k < 70000; k++) g.addSweep(1, 1, {}, {{1.25, 1.25}});
	EXPECT_EQ(g.chunkCount(), chunks);
	EXPECT_EQ(g.cells().size(), cells);
	EXPECT_EQ(g.at(1.25, 1.25).touches, 65535);  // saturates
	// Far away and on negative coordinates: new chunks, the box grows, old cells stay.
	g.addSweep(-5.05, -7.05, {}, {{12.3, 9.1}});
	EXPECT_EQ(g.chunkCount(), chunks + 2);
	EXPECT_EQ(g.at(-5.05, -7.05).passes, 1);
	EXPECT_EQ(g.at(12.3, 9.1).touches, 1);
	EXPECT_EQ(g.at(1.25, 1.25).touches, 65535);
	EXPECT_FALSE(g.at(-5.15, -7.05).explored());
}

TEST(SweptGrid, CopiesShareChunksUntilWritten)
{
	SweptGrid a(0.1);
	a.addSweep(1, 1, {QUARTER}, {});
	a.addSweep(-3, -3, {}, {});  // a second, distant chunk
	ASSERT_EQ(a.chunkCount(), 2u);
	EXPECT_EQ(a.sharedChunks(), 0u);
	SweptGrid b = a;
	EXPECT_EQ(a.sharedChunks(), 2u);
	b.addSweep(1, 1, {}, {{1.25, 1.25}});  // writes into the first chunk only
	EXPECT_EQ(b.sharedChunks(), 1u);
	EXPECT_EQ(b.at(1.25, 1.25).touches, 1);
	EXPECT_EQ(a.at(1.25, 1.25).touches, 0);  // the original did not change
	EXPECT_EQ(a.at(1.0, 1.0).passes, 1);
	EXPECT_EQ(b.at(1.0, 1.0).passes, 2);
}

TEST(SweptGrid, CellsRebuildTheGrid)
{
	SweptGrid a(0.05);
	a.addSweep(-0.3, 0.2, {SweptSector{-0.3, 0.2, 0.6, 2.0, 1.5}}, {{-0.8, 0.4}});
	SweptGrid b(0.05);
	for (const auto& c : a.cells()) b.set(c.ix, c.iy, c.cell);
	ASSERT_EQ(b.cells().size(), a.cells().size());
	ASSERT_GT(a.cells().size(), 50u);
	for (const auto& c : a.cells())
	{
		EXPECT_EQ(b.atIndex(c.ix, c.iy).passes, c.cell.passes);
		EXPECT_EQ(b.atIndex(c.ix, c.iy).touches, c.cell.touches);
	}
	EXPECT_THROW(SweptGrid(0), std::invalid_argument);
}
