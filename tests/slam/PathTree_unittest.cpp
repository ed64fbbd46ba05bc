#include <gtest/gtest.h>
#include <whiskermap/slam/PathTree.h>

#include <algorithm>
#include <random>

using whiskermap::slam::PathTree;
using mrpt::math::TPose2D;

namespace
{
bool samePath(const std::vector<TPose2D>& a, const std::vector<TPose2D>& b)
{
	if (a.size() != b.size()) return false;
	for (size_t k = 0; k < a.size(); k++)
		if (a[k].x != b[k].x || a[k].y != b[k].y || a[k].phi != b[k].phi) return false;
	return true;
}
}  // namespace

TEST(PathTree, PathsAreThoseOfParticlesCopiedWhole)
{
	// Against the plain form: every particle's path a list, copied whole at each resampling.
	std::mt19937 rng(7);
	for (const size_t particles : {1u, 3u, 8u})
	{
		PathTree tree;
		tree.reset(particles, {0.5, -1, 0.1});
		std::vector<std::vector<TPose2D>> plain(particles, {{0.5, -1, 0.1}});
		for (int step = 0; step < 300; step++)
		{
			for (size_t i = 0; i < plain.size(); i++)
			{
				const TPose2D p{double(step), double(i), double(rng() % 1000) / 1000};
				tree.extend(i, p);
				plain[i].push_back(p);
			}
			if (rng() % 3 == 0)
			{
				// Any parents, any count (a filter may change its size), in sorted order.
				std::vector<size_t> parents(1 + rng() % (2 * particles));
				for (auto& q : parents) q = rng() % plain.size();
				std::sort(parents.begin(), parents.end());
				std::vector<std::vector<TPose2D>> next;
				for (const size_t q : parents) next.push_back(plain[q]);
				plain = next;
				tree.resample(parents);
			}
			ASSERT_EQ(tree.particles(), plain.size());
			for (size_t i = 0; i < plain.size(); i++) ASSERT_TRUE(samePath(tree.path(i), plain[i])) << step << " " << i;
		}
	}
}

TEST(PathTree, SharedAncestorsAreStoredOnce)
{
	const size_t particles = 10, steps = 5000;
	PathTree tree;
	tree.reset(particles, {});
	for (size_t step = 0; step < steps; step++)
	{
		for (size_t i = 0; i < particles; i++) tree.extend(i, {double(step), double(i), 0});
		tree.resample(std::vector<size_t>(particles, step % particles));  // all descend from one
	}
	// The start and one lineage of a pose per step (every particle's latest pose is the same
	// parent's): not particles x steps.
	EXPECT_EQ(tree.nodes(), 1 + steps);
	for (size_t i = 0; i < particles; i++) tree.extend(i, {-1, double(i), 0});
	EXPECT_EQ(tree.nodes(), 1 + steps + particles);
	EXPECT_EQ(tree.path(3).size(), steps + 2);
}

TEST(PathTree, WithoutResamplingEveryPathIsItsOwn)
{
	PathTree tree;
	tree.reset(4, {});
	for (int step = 0; step < 100; step++)
		for (size_t i = 0; i < 4; i++) tree.extend(i, {double(step), 0, 0});
	EXPECT_EQ(tree.nodes(), 1 + 4 * 100u);
}

TEST(PathTree, ALongPathIsFreedWithoutRecursionAndItsNodesReused)
{
	PathTree tree;
	tree.reset(1, {});
	for (int step = 0; step < 1000000; step++) tree.extend(0, {double(step), 0, 0});
	EXPECT_EQ(tree.nodes(), 1000001u);
	tree.resample({0, 0});  // two particles share the whole path
	tree.extend(1, {-1, 0, 0});
	EXPECT_EQ(tree.nodes(), 1000002u);
	tree.resample({1});  // the first lineage's leaf goes; the shared path stays
	EXPECT_EQ(tree.nodes(), 1000002u);
	tree.reset(2, {});
	EXPECT_EQ(tree.nodes(), 1u);
}

TEST(PathTree, SettledPosesAreTheStartEveryPathSharesAndAreFreed)
{
	// Against the plain form again: what settle() hands over, followed by path(i), is particle
	// i's whole path, for every i; and it hands over all it can (the particles' paths part at
	// the first pose left, or one of them ends there).
	std::mt19937 rng(11);
	for (const size_t particles : {1u, 2u, 6u})
	{
		PathTree tree;
		tree.reset(particles, {0, 0, 0});
		std::vector<std::vector<TPose2D>> plain(particles, {{0, 0, 0}});
		std::vector<TPose2D> settled;
		for (int step = 0; step < 400; step++)
		{
			for (size_t i = 0; i < plain.size(); i++)
			{
				const TPose2D p{double(step), double(i), double(rng() % 1000) / 1000};
				tree.extend(i, p);
				plain[i].push_back(p);
			}
			if (rng() % 2 == 0)
			{
				std::vector<size_t> parents(particles);
				for (auto& q : parents) q = rng() % (1 + plain.size() / 3);  // few survivors: paths merge
				std::sort(parents.begin(), parents.end());
				std::vector<std::vector<TPose2D>> next;
				for (const size_t q : parents) next.push_back(plain[q]);
				plain = next;
				tree.resample(parents);
			}
			if (rng() % 4 != 0) continue;
			const size_t before = settled.size();
			const size_t handed = tree.settle([&](const TPose2D& p) { settled.push_back(p); });
			EXPECT_EQ(handed, settled.size() - before);
			EXPECT_EQ(tree.settled(), settled.size());
			bool parted = false;
			for (size_t i = 0; i < plain.size(); i++)
			{
				auto whole = settled;
				const auto rest = tree.path(i);
				whole.insert(whole.end(), rest.begin(), rest.end());
				ASSERT_TRUE(samePath(whole, plain[i])) << step << " " << i;
				parted = parted || rest.size() == 1 || !samePath({rest[1]}, {tree.path(0)[1]});
			}
			EXPECT_TRUE(parted) << "settle() left a pose every path shares, step " << step;
		}
		EXPECT_LT(tree.nodes(), 400u * particles / 2);  // the settled poses are freed
	}
}

TEST(PathTree, MergingOlderThanALagGivesEveryPathTheChosenOnesPast)
{
	// Four particles never resampled: four separate paths. After mergeOlderThan(2, 10) each
	// keeps its latest 11 poses (the lag and the latest) and has particle 2's past before
	// them; the pasts only the others held are freed, and settle() can then hand them over.
	PathTree tree;
	tree.reset(4, {});
	std::vector<std::vector<TPose2D>> plain(4, {TPose2D{}});
	for (int step = 0; step < 100; step++)
		for (size_t i = 0; i < 4; i++)
		{
			tree.extend(i, {double(step), double(i), 0});
			plain[i].push_back({double(step), double(i), 0});
		}
	ASSERT_EQ(tree.nodes(), 1 + 4 * 100u);
	tree.mergeOlderThan(2, 10);
	EXPECT_EQ(tree.nodes(), 1 + 100u + 3 * 11u);
	for (size_t i = 0; i < 4; i++)
	{
		auto expected = plain[2];
		std::copy(plain[i].end() - 11, plain[i].end(), expected.end() - 11);
		EXPECT_TRUE(samePath(tree.path(i), expected)) << i;
	}
	std::vector<TPose2D> settled;
	tree.settle([&](const TPose2D& p) { settled.push_back(p); });
	EXPECT_EQ(settled.size(), 101u - 12u);  // the start and particle 2's poses before the meeting one
	EXPECT_EQ(tree.nodes(), 1 + 4 * 11u);  // the meeting pose and each particle's 11
}
