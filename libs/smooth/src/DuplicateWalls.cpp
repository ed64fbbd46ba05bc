#include <whiskermap/smooth/DuplicateWalls.h>
#include <whiskermap/smooth/WallLines.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::smooth
{
namespace
{
/** A group's line: its direction, a point, and its extent along the direction. */
struct Line
{
	bool wall = false;
	double angle = 0;  ///< of the direction, in [0, pi)
	Eigen::Vector2d u{1, 0}, point{0, 0};
	double lo = INFINITY, hi = -INFINITY;
};
}  // namespace

std::vector<DuplicateWalls::TPair> DuplicateWalls::find(
	const std::vector<world::Obstacle>& solids, const std::vector<size_t>& groupOf,
	const std::vector<Eigen::Vector2d>& facing, double distance)
{
	std::vector<Line> lines(facing.size());
	for (size_t i = 0; i < solids.size(); i++)
	{
		if (solids[i].table >= 0) continue;
		const auto angle = WallLines::direction(solids[i]);
		if (!angle) continue;
		const auto& c = solids[i].corners;
		auto& l = lines[groupOf[i]];
		if (!l.wall) l.wall = true, l.angle = *angle, l.u = {std::cos(*angle), std::sin(*angle)}, l.point = (c[0] + c[2]) / 2;
		for (const auto& q : c) l.lo = std::min(l.lo, l.u.dot(q)), l.hi = std::max(l.hi, l.u.dot(q));
	}
	std::vector<TPair> pairs;
	for (size_t a = 0; a < lines.size(); a++)
		for (size_t b = a + 1; b < lines.size(); b++)
		{
			const Line &A = lines[a], &B = lines[b];
			if (!A.wall || !B.wall || facing[a].isZero() || facing[b].isZero()) continue;
			if (!WallLines::parallel(A.angle, B.angle)) continue;
			const Eigen::Vector2d n(-A.u.y(), A.u.x());
			// Touched on their long faces, from the same side.
			if (std::abs(n.dot(facing[a])) < 0.5 * facing[a].norm() || std::abs(n.dot(facing[b])) < 0.5 * facing[b].norm() ||
				facing[a].dot(facing[b]) <= 0)
				continue;
			if (std::abs(n.dot(A.point - B.point)) > distance) continue;
			const bool same = B.u.dot(A.u) > 0;  // B's extent in A's direction
			const double lo = same ? B.lo : -B.hi, hi = same ? B.hi : -B.lo;
			if (std::min(A.hi, hi) <= std::max(A.lo, lo)) continue;  // no overlap along
			pairs.push_back({a, b, n, A.point - B.point});
		}
	return pairs;
}
}  // namespace whiskermap::smooth
