#include <whiskermap/world/Obstacle.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace whiskermap::world
{
Obstacle Obstacle::rectangle(
	const Eigen::Vector2d& centre, double yaw, double halfX, double halfY, double texture,
	int table, int leg)
{
	const Eigen::Rotation2Dd R(yaw);
	Obstacle o;
	o.corners = {
		centre + R * Eigen::Vector2d(halfX, -halfY), centre + R * Eigen::Vector2d(halfX, halfY),
		centre + R * Eigen::Vector2d(-halfX, halfY), centre + R * Eigen::Vector2d(-halfX, -halfY)};
	o.texture = texture;
	o.table = table;
	o.leg = leg;
	return o;
}

Eigen::Vector2d Obstacle::edgeNormal(int k) const
{
	const Eigen::Vector2d e = corners[(k + 1) % 4] - corners[k];
	return Eigen::Vector2d(e.y(), -e.x()).normalized();  // right of a ccw edge = outward
}

double Obstacle::distance(const Eigen::Vector2d& p) const
{
	bool inside = true;
	double best = INFINITY;
	for (int k = 0; k < 4; k++)
	{
		const Eigen::Vector2d a = corners[k], e = corners[(k + 1) % 4] - a;
		if (edgeNormal(k).dot(p - a) > 0) inside = false;
		const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
		best = std::min(best, (p - (a + t * e)).norm());
	}
	return inside ? 0.0 : best;
}
bool Obstacle::intersects(const Obstacle& other) const
{
	// Separated iff some edge normal of either shape has all of the other on its far side.
	auto separates = [](const Obstacle& a, const Obstacle& b) {
		for (int k = 0; k < 4; k++)
		{
			const Eigen::Vector2d n = a.edgeNormal(k);
			bool allOutside = true;
			for (const auto& c : b.corners) allOutside = allOutside && n.dot(c - a.corners[k]) > 0;
			if (allOutside) return true;
		}
		return false;
	};
	return !separates(*this, other) && !separates(other, *this);
}

double Obstacle::gap(const Obstacle& other) const
{
	if (intersects(other)) return 0.0;
	double best = INFINITY;
	for (const auto& c : corners) best = std::min(best, other.distance(c));
	for (const auto& c : other.corners) best = std::min(best, distance(c));
	return best;
}
}  // namespace whiskermap::world
