#include <whiskermap/eval/Hungarian.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace whiskermap::eval
{
std::vector<int> Hungarian::solve(const Eigen::MatrixXd& cost)
{
	const int rows = static_cast<int>(cost.rows()), cols = static_cast<int>(cost.cols());
	const int n = std::max(rows, cols);
	std::vector<int> rowToCol(rows, -1);
	if (rows == 0 || cols == 0) return rowToCol;

	// Forbidden pairs cost more than any difference between sets of allowed pairs, so the
	// optimum has the fewest forbidden pairs, i.e. the most allowed ones. Padding is free.
	double spread = 0;
	for (int i = 0; i < rows; i++)
		for (int j = 0; j < cols; j++)
		{
			const double c = cost(i, j);
			if (std::isnan(c) || c == -INFINITY)
				throw std::invalid_argument("Hungarian: cost is NaN or -infinity");
			if (std::isfinite(c)) spread += std::abs(c);
		}
	const double forbidden = 2 * spread + 1;
	auto a = [&](int i, int j) {
		if (i >= rows || j >= cols) return 0.0;
		return std::isfinite(cost(i, j)) ? cost(i, j) : forbidden;
	};

	// Shortest augmenting paths with row potentials u and column potentials v (1-based;
	// column 0 is the virtual start). match[j] is the row assigned to column j.
	const double inf = std::numeric_limits<double>::infinity();
	std::vector<double> u(n + 1, 0), v(n + 1, 0), minv(n + 1);
	std::vector<int> match(n + 1, 0), way(n + 1, 0);
	std::vector<char> used(n + 1);
	for (int i = 1; i <= n; i++)
	{
		match[0] = i;
		int j0 = 0;
		std::fill(minv.begin(), minv.end(), inf);
		std::fill(used.begin(), used.end(), 0);
		do
		{
			used[j0] = 1;
			const int i0 = match[j0];
			double delta = inf;
			int j1 = 0;
			for (int j = 1; j <= n; j++)
			{
				if (used[j]) continue;
				const double reduced = a(i0 - 1, j - 1) - u[i0] - v[j];
				if (reduced < minv[j]) minv[j] = reduced, way[j] = j0;
				if (minv[j] < delta) delta = minv[j], j1 = j;
			}
			for (int j = 0; j <= n; j++)
			{
				if (used[j]) u[match[j]] += delta, v[j] -= delta;
				else minv[j] -= delta;
			}
			j0 = j1;
		} while (match[j0] != 0);
		do
		{
			const int j1 = way[j0];
			match[j0] = match[j1];
			j0 = j1;
		} while (j0 != 0);
	}
	for (int j = 1; j <= n; j++)
	{
		const int i = match[j] - 1, c = j - 1;
		if (i < rows && c < cols && std::isfinite(cost(i, c))) rowToCol[i] = c;
	}
	return rowToCol;
}
}  // namespace whiskermap::eval
