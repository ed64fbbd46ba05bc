#include <gtest/gtest.h>
#include <whiskermap/baseline/CellSample.h>

#include <numeric>

using whiskermap::baseline::CellSample;

TEST(CellSample, KeepsEverythingInOrderWhileNoCellIsFull)
{
	CellSample<int> s(0.1, 4);
	const double xs[] = {0.05, 0.25, 0.06, -0.3, 0.07, 0.26};
	for (int i = 0; i < 6; i++) s.add(xs[i], 0, i);
	EXPECT_EQ(s.items(), (std::vector<int>{0, 1, 2, 3, 4, 5}));
	EXPECT_EQ(s.seen(), 6u);
	EXPECT_EQ(s.cells(), 3u);
}

TEST(CellSample, AFullCellKeepsAUniformSampleOfItsCap)
{
	CellSample<int> s(1.0, 100);
	for (int i = 0; i < 10000; i++) s.add(0.5, 0.5, i);
	for (int i = 0; i < 50; i++) s.add(3.5, 0.5, -1 - i);  // another cell, not full
	const auto kept = s.items();
	ASSERT_EQ(kept.size(), 150u);
	EXPECT_EQ(s.seen(), 10050u);
	int firstHalf = 0, others = 0;
	for (int v : kept)
	{
		if (v < 0)
			others++;
		else if (v < 5000)
			firstHalf++;
	}
	EXPECT_EQ(others, 50);  // the cell below its cap keeps all
	// Each of the full cell's items is kept with probability 1/100: about half the sample
	// from each half of the stream (binomial, 100 draws: 5 sigma is +-25).
	EXPECT_GT(firstHalf, 25);
	EXPECT_LT(firstHalf, 75);
	EXPECT_TRUE(std::is_sorted(kept.begin(), kept.begin() + 100));  // arrival order
}

TEST(CellSample, TheSameInputGivesTheSameSample)
{
	CellSample<int> a(0.5, 7), b(0.5, 7);
	for (int i = 0; i < 1000; i++) a.add(0.01 * (i % 300), 0, i), b.add(0.01 * (i % 300), 0, i);
	EXPECT_EQ(a.items(), b.items());
	EXPECT_EQ(a.items().size(), 6u * 7u);  // 3 m of cells of 0.5 m, each full
}
