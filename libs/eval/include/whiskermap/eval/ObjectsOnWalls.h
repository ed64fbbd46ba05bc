#pragma once
#include <whiskermap/world/Table.h>
#include <whiskermap/world/World.h>

#include <vector>

namespace whiskermap::eval
{
/** Issue 11's "no object in the map stands on a wall" (doc/evaluation.md): the estimated
 *  objects with a leg (a square of the object's leg width at its corner) that shares a point
 *  with a true wall: an interior wall's slab, or the arena's walls (everything outside the
 *  arena). */
struct ObjectsOnWalls
{
	/** Indices into `estimated` of the objects on a wall of `w`, ascending. */
	static std::vector<size_t> of(const world::World& w, const std::vector<world::Table>& estimated);
};
}  // namespace whiskermap::eval
