#include <whiskermap/smooth/DuplicateLegs.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

namespace whiskermap::smooth
{
namespace
{
/** A table's legs (indices into the solids, by corner) and its shrunk footprint. */
struct MappedTable
{
	std::array<long, 4> legs{-1, -1, -1, -1};
	Eigen::Vector2d centre{0, 0};
	world::Obstacle footprint;
	bool whole = false;  ///< all four legs present, three touched, and the shrunk footprint not empty
};
}  // namespace

std::vector<std::pair<size_t, size_t>> DuplicateLegs::find(
	const std::vector<world::Obstacle>& solids, const std::vector<bool>& touched, double shrink, double distance)
{
	std::map<int, MappedTable> tables;
	for (size_t i = 0; i < solids.size(); i++)
		if (solids[i].table >= 0 && solids[i].leg >= 0 && solids[i].leg < 4)
			tables[solids[i].table].legs[static_cast<size_t>(solids[i].leg)] = static_cast<long>(i);
	for (auto& [id, t] : tables)
	{
		if (t.legs[0] < 0 || t.legs[1] < 0 || t.legs[2] < 0 || t.legs[3] < 0) continue;
		if (std::count_if(t.legs.begin(), t.legs.end(), [&](long i) { return touched[static_cast<size_t>(i)]; }) < 3)
			continue;
		std::array<Eigen::Vector2d, 4> c;
		for (size_t k = 0; k < 4; k++) c[k] = solids[static_cast<size_t>(t.legs[k])].centre();
		t.centre = (c[0] + c[1] + c[2] + c[3]) / 4;
		// Leg 0 is at +x+y, 1 at -x+y, 2 at -x-y (world::Table).
		const Eigen::Vector2d along = c[0] - c[1], across = c[1] - c[2];
		const double hx = along.norm() / 2 - shrink, hy = across.norm() / 2 - shrink;
		if (hx <= 0 || hy <= 0) continue;
		t.footprint = world::Obstacle::rectangle(t.centre, std::atan2(along.y(), along.x()), hx, hy, 0);
		t.whole = true;
	}
	std::set<std::pair<size_t, size_t>> pairs;
	auto add = [&](size_t i, size_t j) { pairs.emplace(std::min(i, j), std::max(i, j)); };
	for (auto a = tables.begin(); a != tables.end(); ++a)
		for (auto b = std::next(a); b != tables.end(); ++b)
		{
			const auto &A = a->second, &B = b->second;
			if (!A.whole || !B.whole || !A.footprint.intersects(B.footprint)) continue;
			for (long bi : B.legs)
			{
				const Eigen::Vector2d rb = solids[static_cast<size_t>(bi)].centre() - B.centre;
				long best = -1;
				double bestDistance = INFINITY;
				for (long ai : A.legs)
				{
					const double d = (solids[static_cast<size_t>(ai)].centre() - A.centre - rb).norm();
					if (d < bestDistance) bestDistance = d, best = ai;
				}
				add(static_cast<size_t>(best), static_cast<size_t>(bi));
			}
		}
	for (size_t i = 0; i < solids.size(); i++)
		for (size_t j = i + 1; j < solids.size(); j++)
			if (solids[i].table >= 0 && solids[j].table >= 0 && solids[i].table != solids[j].table && touched[i] &&
				touched[j] && (solids[i].centre() - solids[j].centre()).norm() <= distance)
				add(i, j);
	return {pairs.begin(), pairs.end()};
}
}  // namespace whiskermap::smooth
