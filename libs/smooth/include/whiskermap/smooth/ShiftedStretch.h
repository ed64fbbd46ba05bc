#pragma once
#include <Eigen/Core>
#include <whiskermap/smooth/ContactFactor.h>
#include <whiskermap/smooth/SameSolidFactor.h>

#include <vector>

namespace whiskermap::smooth
{
/** A stretch of path shifted with what it mapped (eq. S9, doc/slam.md, "A stretch moved with what it mapped").
 *  A filter that drifted for a while, then came back, maps what it touched meanwhile where the
 *  drift put it: a wall or a table a second time, decimetres from the first. Eqs. S4-S6 ask
 *  whether the two copies are one by solving from the path as it is; but the contacts of that
 *  stretch tie to the copy it mapped, and the path cannot leave it by small steps. This is the
 *  jump it cannot make: the copies of one side moved onto the other's, the stretch of path
 *  that touched them moved with them, by t, the copies' mean move,
 *    x_i += w_i t,  d_g += t for every group touched only within the stretch,          (eq. S9)
 *  with w_i = 1 from the first to the last sweep that touched the moved copies, falling
 *  linearly to 0 over `margin` sweeps on either side (1 to the path's end, 0 at its start). */
struct ShiftedStretch
{
	/** Moves `path` and `shifts` (per group) by eq. S9 for `set` (eq. S4-S5 factors: groups a
	 *  and b the two copies), moving the b copies onto the a ones (`bSide`) or the a copies
	 *  onto the b ones; `ties` are the contacts tied at that path. False, and nothing moved,
	 *  when no contact ties to the side to move. */
	static bool move(
		std::vector<Eigen::Vector3d>& path, std::vector<Eigen::Vector2d>& shifts, const std::vector<ContactFactor>& ties,
		const std::vector<SameSolidFactor>& set, bool bSide, size_t margin);
};
}  // namespace whiskermap::smooth
