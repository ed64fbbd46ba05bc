#include <gtest/gtest.h>
#include <whiskermap/model/CowVector.h>

#include <vector>

using whiskermap::model::CowVector;

namespace
{
std::vector<int> values(const CowVector<int, 4>& v)
{
	std::vector<int> out;
	for (size_t i = 0; i < v.size(); i++) out.push_back(v[i]);
	return out;
}
}  // namespace

TEST(CowVector, CopiesShareChunksUntilOneWrites)
{
	CowVector<int, 4> a;
	for (int i = 0; i < 10; i++) a.push_back(i);  // chunks of 4: [0-3] [4-7] [8, 9]
	EXPECT_EQ(a.size(), 10u);
	EXPECT_EQ(a.chunkCount(), 3u);
	EXPECT_EQ(a.sharedChunks(), 0u);

	CowVector<int, 4> b = a;
	EXPECT_EQ(a.sharedChunks(), 3u);
	EXPECT_EQ(b.sharedChunks(), 3u);
	b.edit(5) = 50;  // duplicates the middle chunk only
	EXPECT_EQ(b.sharedChunks(), 2u);
	EXPECT_EQ(a.sharedChunks(), 2u);
	EXPECT_EQ(a[5], 5);
	EXPECT_EQ(b[5], 50);
	b.push_back(10);  // into the shared last chunk: duplicated first
	EXPECT_EQ(a.size(), 10u);
	EXPECT_EQ(b.sharedChunks(), 1u);
	b.growTo(13, -1);  // a new chunk, its own
	EXPECT_EQ(b.chunkCount(), 4u);
	EXPECT_EQ(values(a), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
	EXPECT_EQ(values(b), (std::vector<int>{0, 1, 2, 3, 4, 50, 6, 7, 8, 9, 10, -1, -1}));

	b.edit(6) = 60;  // its chunk is b's alone now: written in place
	EXPECT_EQ(b.sharedChunks(), 1u);
	EXPECT_EQ(a[6], 6);
	b.clear();
	EXPECT_TRUE(b.empty());
	EXPECT_EQ(a.sharedChunks(), 0u);
	EXPECT_EQ(values(a), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
}
