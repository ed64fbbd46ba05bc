#pragma once
#include <Eigen/Core>

#include <array>

namespace whiskermap::world
{
/** A solid convex quadrilateral the whiskers can touch: a table leg, or a wall slab.
 *  Corners are counter-clockwise; edge k runs from corners[k] to corners[k+1]. */
struct Obstacle
{
	std::array<Eigen::Vector2d, 4> corners;
	double texture = 0;  ///< surface texture, [0, 1]
	int table = -1;  ///< index of the table it belongs to, -1 for a wall
	int leg = -1;  ///< leg (corner) index 0..3 within the table, -1 for a wall

	/** An oriented rectangle: centre, yaw, half extents along its own x and y axes. */
	static Obstacle rectangle(
		const Eigen::Vector2d& centre, double yaw, double halfX, double halfY, double texture,
		int table = -1, int leg = -1);

	/** The mean of the four corners. */
	Eigen::Vector2d centre() const { return (corners[0] + corners[1] + corners[2] + corners[3]) / 4; }

	/** Outward unit normal of edge k. */
	Eigen::Vector2d edgeNormal(int k) const;

	/** Euclidean distance from p to the solid (0 inside). */
	double distance(const Eigen::Vector2d& p) const;

	/** True when the two solids share any point (separating-axis test). */
	bool intersects(const Obstacle& other) const;

	/** Gap between the two solids: the shortest distance between them, 0 when they touch or
	 *  overlap (between disjoint convex solids it is reached at a corner of one of them). */
	double gap(const Obstacle& other) const;
};
}  // namespace whiskermap::world
