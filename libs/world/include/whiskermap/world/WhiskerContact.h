#pragma once
#include <Eigen/Core>
#include <whiskermap/world/Obstacle.h>

#include <optional>
#include <vector>

namespace whiskermap::world
{
/** Exact 2-D contact geometry of one whisker against solid obstacles.
 *
 *  The whisker is a straight shaft of length L pivoting at `pivot`; during a whisk its angle
 *  goes monotonically from `a0` to `a1` (|a1 - a0| < 2 pi; a0 == a1 is a fixed whisker) and it
 *  stops at its first touch. The first touch is either at a0 (the shaft already crosses an
 *  obstacle: contact at the nearest crossing along the shaft), or the earliest angle at which
 *  an obstacle corner meets the shaft (within reach) or the tip meets an obstacle edge. */
struct WhiskerContact
{
	double angle = 0;  ///< shaft angle at contact, world frame
	double r = 0;  ///< distance from the pivot to the contact point
	Eigen::Vector2d point;  ///< contact point
	double normal = 0;  ///< outward normal angle of the touched face
	int obstacle = -1;  ///< index into the obstacle list

	/** First contact of the whisk, or nothing if it ends untouched. */
	static std::optional<WhiskerContact> first(
		const Eigen::Vector2d& pivot, double length, double a0, double a1,
		const std::vector<Obstacle>& obstacles);
};
}  // namespace whiskermap::world
