#include <whiskermap/world/Table.h>

#include <Eigen/Geometry>

namespace whiskermap::world
{
Eigen::Vector2d Table::legCentre(int k) const
{
	const double sx = (k == 0 || k == 3) ? 1 : -1, sy = (k < 2) ? 1 : -1;
	return Eigen::Vector2d(x, y) +
		   Eigen::Rotation2Dd(yaw) * Eigen::Vector2d(sx * length / 2, sy * width / 2);
}

Obstacle Table::leg(int k, int self) const
{
	return Obstacle::rectangle(legCentre(k), yaw, leg_width / 2, leg_width / 2, texture, self, k);
}

Obstacle Table::footprint() const
{
	return Obstacle::rectangle(
		{x, y}, yaw, (length + leg_width) / 2, (width + leg_width) / 2, texture);
}
}  // namespace whiskermap::world
