#pragma once
#include <Eigen/Core>
#include <whiskermap/world/Obstacle.h>

#include <cstddef>
#include <vector>

namespace whiskermap::smooth
{
/** Walls a map holds twice. A particle that drifted along a wall before it reached its end
 *  maps the next wall where the drift put it, and maps it again, centimetres to decimetres
 *  away, on a later visit (doc/slam.md, "Tables mapped twice"). Two groups of wall pieces
 *  (WallLines: each group on one line) are taken for one wall when their lines are parallel
 *  (within 1 degree), at most `distance` apart across, overlap along, and the contacts touched
 *  both on the same side: a robot on that side of the nearer one could not reach the other. */
struct DuplicateWalls
{
	struct TPair
	{
		size_t a = 0, b = 0;  ///< the two groups, a < b
		Eigen::Vector2d normal{0, 1};  ///< across both lines
		Eigen::Vector2d offset{0, 0};  ///< a point of a's line minus a point of b's
	};

	/** `facing[g]`: the sum of the outward normals of the faces the contacts tied to group g
	 *  touched (zero: untouched); only walls (table < 0) are read. Each pair once. */
	static std::vector<TPair> find(
		const std::vector<world::Obstacle>& solids, const std::vector<size_t>& groupOf,
		const std::vector<Eigen::Vector2d>& facing, double distance);
};
}  // namespace whiskermap::smooth
