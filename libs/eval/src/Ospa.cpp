#include <whiskermap/core/Error.h>
#include <whiskermap/eval/SparseAssignment.h>
#include <whiskermap/eval/Ospa.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::eval
{
double Ospa::distance(
	const std::vector<Eigen::Vector2d>& X, const std::vector<Eigen::Vector2d>& Y, double c,
	double p)
{
	if (!(c > 0) || !(p >= 1)) throw core::Error("OSPA: need cut-off c > 0 and order p >= 1");
	const auto& small = X.size() <= Y.size() ? X : Y;
	const auto& large = X.size() <= Y.size() ? Y : X;
	if (large.empty()) return 0;
	if (small.empty()) return c;
	// Pairs at c or farther cost c^p, as much as leaving them unmatched: only nearer pairs
	// are scored, as d^p - c^p (< 0) against 0 for unmatched, per connected component:
	// total = c^p n + the least sum over a matching.
	auto pairs = SparseAssignment::near(small, large, c);
	for (auto& q : pairs) q.cost = std::pow(q.cost, p) - std::pow(c, p);
	const auto assignment = SparseAssignment::solve(static_cast<int>(small.size()), static_cast<int>(large.size()), pairs, 0.0);
	double sum = std::pow(c, p) * double(large.size());
	for (const auto& q : pairs)
		if (assignment[q.row] == q.col) sum += q.cost;
	sum = std::max(sum, 0.0);
	return std::pow(sum / double(large.size()), 1 / p);
}
}  // namespace whiskermap::eval
