#include <whiskermap/core/Error.h>
#include <whiskermap/world/PathPlanner.h>

#include <algorithm>
#include <cmath>
#include <queue>

namespace whiskermap::world
{
namespace
{
const int DX[8] = {1, -1, 0, 0, 1, 1, -1, -1}, DY[8] = {0, 0, 1, -1, 1, -1, 1, -1};
}

PathPlanner::PathPlanner(const World& w, double robotRadius, double clearance, double cell)
	: m_x0(w.x_min),
	  m_y0(w.y_min),
	  m_cell(cell),
	  m_nx(static_cast<int>(std::ceil((w.x_max - w.x_min) / cell))),
	  m_ny(static_cast<int>(std::ceil((w.y_max - w.y_min) / cell)))
{
	if (double(m_nx) * m_ny > 2e7)
		throw core::Error("arena too large for the path planner (more than 2e7 cells of " + std::to_string(cell) + " m)");
	m_free.assign(size_t(m_nx) * m_ny, 1);
	const double keep = robotRadius + clearance + cell * std::sqrt(0.5);
	for (const auto& o : w.obstacles())
	{
		double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
		for (const auto& c : o.corners)
			for (int k = 0; k < 2; k++) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
		const int i0 = std::max(0, int(std::floor((lo[0] - keep - m_x0) / cell)));
		const int i1 = std::min(m_nx - 1, int(std::floor((hi[0] + keep - m_x0) / cell)));
		const int j0 = std::max(0, int(std::floor((lo[1] - keep - m_y0) / cell)));
		const int j1 = std::min(m_ny - 1, int(std::floor((hi[1] + keep - m_y0) / cell)));
		for (int j = j0; j <= j1; j++)
			for (int i = i0; i <= i1; i++)
				if (o.distance(centre(j * m_nx + i)) < keep) m_free[size_t(j) * m_nx + i] = 0;
	}
	// The largest 8-connected free region (moves as in astar: no corner cutting).
	m_inRegion.assign(m_free.size(), 0);
	std::vector<int> label(m_free.size(), -1), members;
	for (int s = 0; s < int(m_free.size()); s++)
	{
		if (!m_free[s] || label[s] >= 0) continue;
		members.clear();
		label[s] = s;
		members.push_back(s);
		for (size_t q = 0; q < members.size(); q++)
		{
			const int c = members[q], ci = c % m_nx, cj = c / m_nx;
			for (int k = 0; k < 8; k++)
			{
				const int i = ci + DX[k], j = cj + DY[k], n = j * m_nx + i;
				if (i < 0 || j < 0 || i >= m_nx || j >= m_ny || !m_free[n] || label[n] >= 0) continue;
				if (k >= 4 && (!m_free[cj * m_nx + i] || !m_free[j * m_nx + ci])) continue;
				label[n] = s;
				members.push_back(n);
			}
		}
		if (members.size() > m_region.size()) m_region = members;
	}
	if (m_region.empty()) throw core::Error("the robot body fits nowhere in the arena");
	std::sort(m_region.begin(), m_region.end());
	for (int c : m_region) m_inRegion[c] = 1;
}

int PathPlanner::cellOf(const Eigen::Vector2d& p) const
{
	const int i = int(std::floor((p.x() - m_x0) / m_cell)), j = int(std::floor((p.y() - m_y0) / m_cell));
	return i < 0 || j < 0 || i >= m_nx || j >= m_ny ? -1 : j * m_nx + i;
}

Eigen::Vector2d PathPlanner::centre(int c) const
{
	return {m_x0 + (c % m_nx + 0.5) * m_cell, m_y0 + (c / m_nx + 0.5) * m_cell};
}

bool PathPlanner::free(const Eigen::Vector2d& p) const
{
	const int c = cellOf(p);
	return c >= 0 && m_free[c];
}

bool PathPlanner::segmentFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
{
	const int n = std::max(1, int(std::ceil((b - a).norm() / (m_cell / 2))));
	for (int k = 0; k <= n; k++)
		if (!free(a + (b - a) * (double(k) / n))) return false;
	return true;
}

bool PathPlanner::inRegion(const Eigen::Vector2d& p) const
{
	const int c = cellOf(p);
	return c >= 0 && m_inRegion[c];
}

Eigen::Vector2d PathPlanner::reachable(const Eigen::Vector2d& p) const
{
	if (inRegion(p)) return p;
	int best = m_region.front();
	double bestD = INFINITY;
	for (int r : m_region)
		if (const double d = (centre(r) - p).squaredNorm(); d < bestD) bestD = d, best = r;
	return centre(best);
}

std::vector<int> PathPlanner::astar(int from, int to) const
{
	// A* over 8-neighbours (diagonals only past two free sides), octile heuristic.
	const auto h = [&](int c) {
		const double dx = std::abs(c % m_nx - to % m_nx), dy = std::abs(c / m_nx - to / m_nx);
		return std::max(dx, dy) + (std::sqrt(2.0) - 1) * std::min(dx, dy);
	};
	std::vector<double> g(m_free.size(), INFINITY);
	std::vector<int> parent(m_free.size(), -1);
	using Item = std::pair<double, int>;
	std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
	g[from] = 0;
	open.push({h(from), from});
	while (!open.empty())
	{
		const auto [f, c] = open.top();
		open.pop();
		if (c == to) break;
		if (f > g[c] + h(c) + 1e-9) continue;  // stale entry
		const int ci = c % m_nx, cj = c / m_nx;
		for (int k = 0; k < 8; k++)
		{
			const int i = ci + DX[k], j = cj + DY[k], n = j * m_nx + i;
			if (i < 0 || j < 0 || i >= m_nx || j >= m_ny || !m_free[n]) continue;
			if (k >= 4 && (!m_free[cj * m_nx + i] || !m_free[j * m_nx + ci])) continue;
			const double ng = g[c] + (k < 4 ? 1 : std::sqrt(2.0));
			if (ng >= g[n]) continue;
			g[n] = ng;
			parent[n] = c;
			open.push({ng + h(n), n});
		}
	}
	std::vector<int> cells;
	for (int c = to; c != -1; c = parent[c]) cells.push_back(c);
	std::reverse(cells.begin(), cells.end());
	return cells;
}

std::vector<Eigen::Vector2d> PathPlanner::route(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const
{
	if (segmentFree(a, b)) return {a, b};
	const int from = cellOf(a), to = cellOf(b);
	if (from < 0 || to < 0 || !m_inRegion[from] || !m_inRegion[to])
		throw core::Error("PathPlanner::route: an end lies outside the reachable region");
	std::vector<Eigen::Vector2d> cells{a};
	for (int c : astar(from, to)) cells.push_back(centre(c));
	cells.push_back(b);
	// Straighten: from each kept point, go as far along the cells as stays free.
	std::vector<Eigen::Vector2d> out{a};
	for (size_t i = 0; i + 1 < cells.size();)
	{
		size_t j = i + 1;
		while (j + 1 < cells.size() && segmentFree(cells[i], cells[j + 1])) j++;
		out.push_back(cells[j]);
		i = j;
	}
	return out;
}
}  // namespace whiskermap::world
