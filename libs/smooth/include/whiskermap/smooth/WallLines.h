#pragma once
#include <whiskermap/world/Obstacle.h>

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
};
}  // namespace whiskermap::smooth
