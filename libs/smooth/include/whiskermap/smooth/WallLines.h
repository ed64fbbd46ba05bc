#pragma once
#include <whiskermap/world/Obstacle.h>

#include <optional>
#include <vector>

namespace whiskermap::smooth
{
/** Walls mapped in pieces, one line. A particle maps a long wall piece by piece, each where
 *  the drift of the moment put it: the pieces of one straight wall end up on parallel lines
 *  centimetres apart. Pieces of walls (solids with table < 0) whose centre lines are parallel
 *  (within 1 degree) and within `distance` of each other across are taken for one wall: each
 *  is moved across onto the length-weighted mean line of its set, and the set shares one
 *  group (one shift) in the smoother. Chains merge: pieces a-b and b-c within `distance`
 *  make one set. */
struct WallLines
{
	/** Moves the pieces in `solids` and renumbers `groupOf` (groups stay 0..count-1);
	 *  returns the new group count. */
	static size_t merge(std::vector<world::Obstacle>& solids, std::vector<size_t>& groupOf, double distance);

	/** A wall piece's long axis: the longer of its two sides, as a vector. */
	static Eigen::Vector2d longAxis(const world::Obstacle& piece);

	/** The direction of a wall piece's long axis, radians in [0, pi); nothing for a piece of
	 *  zero length. */
	static std::optional<double> direction(const world::Obstacle& piece);

	/** True when two such directions are parallel within 1 degree. */
	static bool parallel(double a, double b);
};
}  // namespace whiskermap::smooth
