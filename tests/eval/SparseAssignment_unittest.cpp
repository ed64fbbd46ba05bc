#include <gtest/gtest.h>
#include <whiskermap/eval/Hungarian.h>
#include <whiskermap/eval/Ospa.h>
#include <whiskermap/eval/SparseAssignment.h>

#include <cmath>
#include <random>

using namespace whiskermap::eval;

namespace
{
std::vector<Eigen::Vector2d> points(std::mt19937& rng, size_t n, double span)
{
	std::uniform_real_distribution<double> u(0, span);
	std::vector<Eigen::Vector2d> p;
	for (size_t i = 0; i < n; i++) p.emplace_back(u(rng), u(rng));
	return p;
}

/** OSPA as it was computed before issue 8: one dense Hungarian over every pair. */
double denseOspa(const std::vector<Eigen::Vector2d>& X, const std::vector<Eigen::Vector2d>& Y, double c, double p)
{
	const auto& small = X.size() <= Y.size() ? X : Y;
	const auto& large = X.size() <= Y.size() ? Y : X;
	if (large.empty()) return 0;
	if (small.empty()) return c;
	Eigen::MatrixXd cost(small.size(), large.size());
	for (size_t i = 0; i < small.size(); i++)
		for (size_t j = 0; j < large.size(); j++) cost(i, j) = std::pow(std::min(c, (small[i] - large[j]).norm()), p);
	const auto a = Hungarian::solve(cost);
	double sum = std::pow(c, p) * double(large.size() - small.size());
	for (size_t i = 0; i < small.size(); i++) sum += cost(i, a[i]);
	return std::pow(sum / double(large.size()), 1 / p);
}
}  // namespace

// The split by components changes nothing: same number of matches and same total cost as
// one dense Hungarian over the gated matrix, on random instances.
TEST(SparseAssignment, EqualsDenseHungarianOnGatedPairs)
{
	std::mt19937 rng(8);
	for (int trial = 0; trial < 200; trial++)
	{
		const auto a = points(rng, 1 + rng() % 30, 4), b = points(rng, 1 + rng() % 30, 4);
		const double gate = 0.2 + 0.1 * (rng() % 8);
		const auto pairs = SparseAssignment::near(a, b, gate);
		Eigen::MatrixXd dense = Eigen::MatrixXd::Constant(a.size(), b.size(), INFINITY);
		size_t count = 0;
		for (size_t i = 0; i < a.size(); i++)
			for (size_t j = 0; j < b.size(); j++)
				if ((a[i] - b[j]).norm() <= gate) dense(i, j) = (a[i] - b[j]).norm(), count++;
		ASSERT_EQ(pairs.size(), count);
		const auto sparse = SparseAssignment::solve(int(a.size()), int(b.size()), pairs, INFINITY);
		const auto full = Hungarian::solve(dense);
		size_t ns = 0, nf = 0;
		double cs = 0, cf = 0;
		for (size_t i = 0; i < a.size(); i++)
		{
			if (sparse[i] >= 0) ns++, cs += dense(i, sparse[i]);
			if (full[i] >= 0) nf++, cf += dense(i, full[i]);
		}
		EXPECT_EQ(ns, nf) << trial;
		EXPECT_NEAR(cs, cf, 1e-9) << trial;
	}
}

TEST(SparseAssignment, OspaEqualsTheDenseComputation)
{
	std::mt19937 rng(9);
	for (int trial = 0; trial < 200; trial++)
	{
		const auto a = points(rng, rng() % 25, 3), b = points(rng, rng() % 25, 3);
		const double c = 0.2 + 0.2 * (rng() % 5), p = 1 + rng() % 3;
		EXPECT_NEAR(Ospa::distance(a, b, c, p), denseOspa(a, b, c, p), 1e-9) << trial;
	}
}

TEST(SparseAssignment, TenThousandTablesSplitIntoSmallComponents)
{
	// A 100 x 100 grid of tables 2 m apart, estimates near each: 10,000 components of one
	// pair (a dense Hungarian would be a 10,000 x 10,000 cubic solve).
	std::vector<Eigen::Vector2d> truth, est;
	for (int i = 0; i < 100; i++)
		for (int j = 0; j < 100; j++) truth.emplace_back(2.0 * i, 2.0 * j), est.emplace_back(2.0 * i + 0.05, 2.0 * j);
	const auto pairs = SparseAssignment::near(truth, est, 0.25);
	ASSERT_EQ(pairs.size(), 10000u);
	const auto a = SparseAssignment::solve(10000, 10000, pairs, INFINITY);
	for (int i = 0; i < 10000; i++) ASSERT_EQ(a[i], i);
}
