#include <whiskermap/smooth/WallLines.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace whiskermap::smooth
{
namespace
{
struct Piece
{
	size_t solid;
	double angle;  ///< of the long axis, in [0, pi)
	Eigen::Vector2d normal;  ///< across the long axis
	double across, length;
};

size_t find(std::vector<size_t>& parent, size_t i)
{
	while (parent[i] != i) i = parent[i] = parent[parent[i]];
	return i;
}
}  // namespace

Eigen::Vector2d WallLines::longAxis(const world::Obstacle& piece)
{
	const auto& c = piece.corners;
	return (c[2] - c[1]).norm() > (c[1] - c[0]).norm() ? Eigen::Vector2d(c[2] - c[1]) : Eigen::Vector2d(c[1] - c[0]);
}

std::optional<double> WallLines::direction(const world::Obstacle& piece)
{
	const Eigen::Vector2d axis = longAxis(piece);
	if (axis.norm() <= 0) return std::nullopt;
	double angle = std::atan2(axis.y(), axis.x());
	if (angle < 0) angle += M_PI;
	if (angle >= M_PI) angle -= M_PI;
	return angle;
}

bool WallLines::parallel(double a, double b)
{
	const double d = std::abs(a - b);
	return std::min(d, M_PI - d) <= M_PI / 180;
}

size_t WallLines::merge(std::vector<world::Obstacle>& solids, std::vector<size_t>& groupOf, double distance)
{
	std::vector<Piece> pieces;
	for (size_t i = 0; i < solids.size(); i++)
	{
		if (solids[i].table >= 0) continue;
		const auto angle = direction(solids[i]);
		if (!angle) continue;
		const double length = longAxis(solids[i]).norm();
		const Eigen::Vector2d normal(-std::sin(*angle), std::cos(*angle));
		pieces.push_back({i, *angle, normal, normal.dot(solids[i].centre()), length});
	}
	std::vector<size_t> parent(pieces.size());
	std::iota(parent.begin(), parent.end(), 0);
	for (size_t a = 0; a < pieces.size(); a++)
		for (size_t b = a + 1; b < pieces.size(); b++)
		{
			if (!parallel(pieces[a].angle, pieces[b].angle)) continue;
			// Across pieces a's normal (parallel within a degree: either normal will do).
			const double across = std::abs(pieces[a].normal.dot(
				solids[pieces[b].solid].corners[0] + solids[pieces[b].solid].corners[2] -
				solids[pieces[a].solid].corners[0] - solids[pieces[a].solid].corners[2]) / 2);
			if (across < distance) parent[find(parent, a)] = find(parent, b);
		}
	// Each set: its length-weighted mean line (in its root's normal), every piece moved onto it.
	std::map<size_t, std::pair<double, double>> line;  // root -> (sum length x across, sum length)
	for (size_t a = 0; a < pieces.size(); a++)
	{
		const auto& root = pieces[find(parent, a)];
		const Eigen::Vector2d& c0 = solids[pieces[a].solid].corners[0];
		const Eigen::Vector2d& c2 = solids[pieces[a].solid].corners[2];
		auto& l = line[find(parent, a)];
		l.first += pieces[a].length * root.normal.dot((c0 + c2) / 2);
		l.second += pieces[a].length;
	}
	std::map<size_t, size_t> setGroup;  // root -> the group of the set's first piece
	for (size_t a = 0; a < pieces.size(); a++)
	{
		const size_t r = find(parent, a);
		const auto& n = pieces[r].normal;
		auto& o = solids[pieces[a].solid];
		const double target = line[r].first / line[r].second;
		const Eigen::Vector2d move = n * (target - n.dot((o.corners[0] + o.corners[2]) / 2));
		for (auto& c : o.corners) c += move;
		const auto [it, added] = setGroup.emplace(r, groupOf[pieces[a].solid]);
		groupOf[pieces[a].solid] = it->second;
	}
	// Renumber the groups still in use: 0..count-1, in order of first use.
	std::map<size_t, size_t> renumber;
	for (auto& g : groupOf) g = renumber.emplace(g, renumber.size()).first->second;
	return renumber.size();
}
}  // namespace whiskermap::smooth
