#include <whiskermap/eval/ObjectsOnWalls.h>

#include <algorithm>

namespace whiskermap::eval
{
std::vector<size_t> ObjectsOnWalls::of(const world::World& w, const std::vector<world::Table>& estimated)
{
	// The arena's walls as slabs just outside it, so thick (1000 km) that they hold everything
	// outside it (World::obstacles), then the interior walls' slabs: the obstacles of no table.
	constexpr double OUTSIDE = 1e6;
	std::vector<world::Obstacle> walls;
	for (const auto& o : w.obstacles(OUTSIDE))
		if (o.table < 0) walls.push_back(o);
	std::vector<size_t> on;
	for (size_t i = 0; i < estimated.size(); i++)
		for (int k = 0; k < 4; k++)
		{
			const auto leg = estimated[i].leg(k, static_cast<int>(i));
			if (std::any_of(walls.begin(), walls.end(), [&](const world::Obstacle& s) { return leg.intersects(s); }))
			{
				on.push_back(i);
				break;
			}
		}
	return on;
}
}  // namespace whiskermap::eval
