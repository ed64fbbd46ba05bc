#pragma once
#include <whiskermap/world/Obstacle.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace whiskermap::smooth
{
/** Legs a map holds twice. A particle that comes back to a table after drifting maps it a
 *  second time beside the first (doc/slam.md, "Tables mapped twice"). Two tables cannot
 *  stand in one place, so:
 *  - two mapped tables whose footprints (the quadrilaterals of their leg centres), each
 *    shrunk by `shrink` on every side, still overlap are one table, when each has at least
 *    three legs touched (then its footprint is where the contacts put it: with two, the
 *    other two legs may stand on the wrong side). Each leg of one is paired with the leg of
 *    the other at the same place relative to its table's centre;
 *  - touched legs of two different tables whose centres lie within `distance` are one leg.
 *  The solids are mappedSolids()'s: legs carry their table index and corner (0..3); walls
 *  (table < 0) are left out. `touched[i]`: contacts tie to solid i. */
struct DuplicateLegs
{
	/** Pairs (i, j), i < j, of indices into `solids` that are the same leg; each pair once. */
	static std::vector<std::pair<size_t, size_t>> find(
		const std::vector<world::Obstacle>& solids, const std::vector<bool>& touched, double shrink, double distance);
};
}  // namespace whiskermap::smooth
