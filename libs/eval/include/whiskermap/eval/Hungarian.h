#pragma once
#include <Eigen/Core>

#include <vector>

namespace whiskermap::eval
{
/** Optimal one-to-one assignment (Kuhn-Munkres with potentials, O(n^3), n = max(rows, cols)).
 *
 *  `cost(i, j)` is the cost of assigning row i to column j; +infinity forbids the pair (a gated
 *  out match). The matrix may be rectangular. Among all assignments the result first has the
 *  most allowed pairs, then the least total cost of those pairs. */
struct Hungarian
{
	/** Column of each row, or -1 when the row stays unassigned. Throws std::invalid_argument
	 *  on a NaN or -infinity cost. */
	static std::vector<int> solve(const Eigen::MatrixXd& cost);
};
}  // namespace whiskermap::eval
