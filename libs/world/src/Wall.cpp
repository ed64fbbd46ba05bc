#include <whiskermap/world/Wall.h>

#include <cmath>

namespace whiskermap::world
{
double Wall::length() const
{
	return std::hypot(x1 - x0, y1 - y0);
}

Obstacle Wall::slab() const
{
	const Eigen::Vector2d centre((x0 + x1) / 2, (y0 + y1) / 2);
	return Obstacle::rectangle(centre, std::atan2(y1 - y0, x1 - x0), length() / 2, thickness / 2, texture);
}
}  // namespace whiskermap::world
