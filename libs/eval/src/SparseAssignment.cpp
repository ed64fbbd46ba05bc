#include <whiskermap/eval/Hungarian.h>
#include <whiskermap/eval/SparseAssignment.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace whiskermap::eval
{
namespace
{
int find(std::vector<int>& parent, int x)
{
	while (parent[x] != x) x = parent[x] = parent[parent[x]];
	return x;
}
int64_t cellOf(double v, double cell) { return static_cast<int64_t>(std::clamp(std::floor(v / cell), -1e15, 1e15)); }
int64_t key(int64_t ix, int64_t iy) { return static_cast<int64_t>((static_cast<uint64_t>(ix) << 32) ^ static_cast<uint32_t>(iy)); }
}  // namespace

std::vector<int> SparseAssignment::solve(int rows, int cols, const std::vector<Pair>& pairs, double missing)
{
	std::vector<int> rowToCol(rows, -1);
	// Components over rows (0..rows-1) and columns (rows..rows+cols-1).
	std::vector<int> parent(rows + cols);
	std::iota(parent.begin(), parent.end(), 0);
	for (const auto& p : pairs) parent[find(parent, p.row)] = find(parent, rows + p.col);
	std::unordered_map<int, std::vector<int>> members;  // root -> rows and columns, in order
	for (int v = 0; v < rows + cols; v++) members[find(parent, v)].push_back(v);
	std::unordered_map<int, std::vector<const Pair*>> edges;
	for (const auto& p : pairs) edges[find(parent, p.row)].push_back(&p);
	for (const auto& [root, es] : edges)
	{
		std::vector<int> r, c, local(rows + cols, -1);
		for (int v : members[root])
		{
			if (v < rows)
				local[v] = static_cast<int>(r.size()), r.push_back(v);
			else
				local[v] = static_cast<int>(c.size()), c.push_back(v - rows);
		}
		Eigen::MatrixXd cost = Eigen::MatrixXd::Constant(static_cast<Eigen::Index>(r.size()), static_cast<Eigen::Index>(c.size()), missing);
		std::vector<char> listed(r.size() * c.size(), 0);
		for (const Pair* p : es)
		{
			const int i = local[p->row], j = local[rows + p->col];
			cost(i, j) = p->cost;
			listed[i * c.size() + j] = 1;
		}
		const auto a = Hungarian::solve(cost);
		for (size_t i = 0; i < r.size(); i++)
			if (a[i] >= 0 && listed[i * c.size() + a[i]]) rowToCol[r[i]] = c[a[i]];
	}
	return rowToCol;
}

std::vector<SparseAssignment::Pair> SparseAssignment::near(
	const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b, double radius)
{
	if (a.size() < b.size())
	{
		// Index the smaller set: the grid is rebuilt per call (per pose, in per-pose scoring).
		auto out = near(b, a, radius);
		for (auto& p : out) std::swap(p.row, p.col);
		std::sort(out.begin(), out.end(), [](const Pair& x, const Pair& y) { return x.row != y.row ? x.row < y.row : x.col < y.col; });
		return out;
	}
	std::vector<Pair> out;
	const double cell = std::max(radius, 1e-9);
	std::unordered_map<int64_t, std::vector<int>> grid;
	for (int j = 0; j < static_cast<int>(b.size()); j++) grid[key(cellOf(b[j].x(), cell), cellOf(b[j].y(), cell))].push_back(j);
	for (int i = 0; i < static_cast<int>(a.size()); i++)
	{
		const auto first = out.size();
		const int64_t cx = cellOf(a[i].x(), cell), cy = cellOf(a[i].y(), cell);
		for (int64_t dx = -1; dx <= 1; dx++)
			for (int64_t dy = -1; dy <= 1; dy++)
				if (const auto it = grid.find(key(cx + dx, cy + dy)); it != grid.end())
					for (const int j : it->second)
					{
						const double d = (a[i] - b[j]).norm();
						if (d <= radius) out.push_back({i, j, d});
					}
		std::sort(out.begin() + static_cast<std::ptrdiff_t>(first), out.end(), [](const Pair& x, const Pair& y) { return x.col < y.col; });
	}
	return out;
}
}  // namespace whiskermap::eval
