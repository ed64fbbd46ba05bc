#include <gtest/gtest.h>
#include <whiskermap/eval/Hungarian.h>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>

using whiskermap::eval::Hungarian;

namespace
{
const double X = INFINITY;  // a gated-out pair

struct Outcome
{
	size_t matched = 0;
	double cost = 0;
};

/** Checks `a` is a valid assignment of allowed pairs and returns its size and cost. */
Outcome check(const Eigen::MatrixXd& c, const std::vector<int>& a)
{
	EXPECT_EQ(a.size(), size_t(c.rows()));
	Outcome o;
	std::set<int> cols;
	for (size_t i = 0; i < a.size(); i++)
	{
		if (a[i] < 0) continue;
		EXPECT_LT(a[i], c.cols());
		EXPECT_TRUE(cols.insert(a[i]).second) << "column used twice";
		EXPECT_TRUE(std::isfinite(c(i, a[i]))) << "gated-out pair assigned";
		o.matched++;
		o.cost += c(i, a[i]);
	}
	return o;
}

/** Every partial injective assignment: best = most pairs, then least cost. */
void bruteForce(const Eigen::MatrixXd& c, int row, std::vector<bool>& used, Outcome cur, Outcome& best)
{
	if (row == c.rows())
	{
		if (cur.matched > best.matched || (cur.matched == best.matched && cur.cost < best.cost))
			best = cur;
		return;
	}
	bruteForce(c, row + 1, used, cur, best);  // leave this row unassigned
	for (int j = 0; j < c.cols(); j++)
	{
		if (used[j] || !std::isfinite(c(row, j))) continue;
		used[j] = true;
		bruteForce(c, row + 1, used, {cur.matched + 1, cur.cost + c(row, j)}, best);
		used[j] = false;
	}
}

Eigen::MatrixXd matrix(int rows, int cols, std::initializer_list<double> v)
{
	Eigen::MatrixXd m(rows, cols);
	auto it = v.begin();
	for (int i = 0; i < rows; i++)
		for (int j = 0; j < cols; j++) m(i, j) = *it++;
	return m;
}
}  // namespace

TEST(Hungarian, SquareKnownOptimum)
{
	const auto c = matrix(3, 3, {4, 1, 3, 2, 0, 5, 3, 2, 2});
	const auto a = Hungarian::solve(c);
	EXPECT_EQ(a, (std::vector<int>{1, 0, 2}));
	EXPECT_DOUBLE_EQ(check(c, a).cost, 5);
}

TEST(Hungarian, Rectangular)
{
	// More columns than rows: every row assigned, the cheapest columns chosen.
	const auto wide = matrix(2, 4, {9, 2, 7, 1, 3, 8, 8, 1});
	EXPECT_EQ(Hungarian::solve(wide), (std::vector<int>{1, 3}));
	// More rows than columns: one row left out.
	const auto tall = matrix(3, 2, {1, 5, 2, 3, 9, 9});
	EXPECT_EQ(Hungarian::solve(tall), (std::vector<int>{0, 1, -1}));
}

TEST(Hungarian, GatedOutPairsAreNeverAssigned)
{
	EXPECT_EQ(Hungarian::solve(matrix(2, 2, {X, X, X, X})), (std::vector<int>{-1, -1}));
	EXPECT_EQ(Hungarian::solve(matrix(2, 2, {X, 3, X, 1})), (std::vector<int>{-1, 1}));
	// Most pairs first: the two-pair assignment (cost 12) beats the cheaper single pair (1).
	EXPECT_EQ(Hungarian::solve(matrix(2, 2, {1, 2, 10, X})), (std::vector<int>{1, 0}));
}

TEST(Hungarian, EmptyAndInvalid)
{
	EXPECT_TRUE(Hungarian::solve(Eigen::MatrixXd(0, 3)).empty());
	EXPECT_EQ(Hungarian::solve(Eigen::MatrixXd(2, 0)), (std::vector<int>{-1, -1}));
	EXPECT_THROW(Hungarian::solve(matrix(1, 2, {1, NAN})), std::invalid_argument);
	EXPECT_THROW(Hungarian::solve(matrix(1, 1, {-X})), std::invalid_argument);
}

TEST(Hungarian, MatchesBruteForceOnRandomMatrices)
{
	std::mt19937 rng(2011);
	std::uniform_int_distribution<int> size(0, 5);
	std::uniform_real_distribution<double> value(-2.0, 10.0), gate(0, 1);
	for (int trial = 0; trial < 2000; trial++)
	{
		Eigen::MatrixXd c(size(rng), size(rng));
		const double pGated = gate(rng);
		for (int i = 0; i < c.rows(); i++)
			for (int j = 0; j < c.cols(); j++) c(i, j) = gate(rng) < pGated ? X : value(rng);
		Outcome best;
		std::vector<bool> used(c.cols(), false);
		bruteForce(c, 0, used, {}, best);
		const auto got = check(c, Hungarian::solve(c));
		ASSERT_EQ(got.matched, best.matched) << "trial " << trial << "\n" << c;
		ASSERT_NEAR(got.cost, best.cost, 1e-9) << "trial " << trial << "\n" << c;
	}
}
