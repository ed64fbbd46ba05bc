#pragma once
#include <Eigen/Core>

#include <vector>

namespace whiskermap::eval
{
/** Optimal assignment when only some pairs may be matched (a gate): the pairs split into
 *  connected components, each solved by Hungarian on its own small matrix. Rows and columns
 *  of different components never interact, so the result equals one Hungarian over the whole
 *  matrix, in time set by the largest component (seconds for 10,000 tables, not hours).
 *  Also finds the pairs: points within `radius` of each other, through a uniform grid. */
struct SparseAssignment
{
	struct Pair
	{
		int row, col;
		double cost;
	};

	/** Row -> column (or -1). `missing` is the cost of a pair not listed: +infinity means
	 *  forbidden (Hungarian's rule: most listed pairs first, then least total cost); 0 means
	 *  "as good as unmatched" (least total cost). Only listed pairs are ever returned. */
	static std::vector<int> solve(int rows, int cols, const std::vector<Pair>& pairs, double missing);

	/** Every (i, j) with |a_i - b_j| <= radius, cost = that distance, in (i, j) order. */
	static std::vector<Pair> near(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double radius);
};
}  // namespace whiskermap::eval
