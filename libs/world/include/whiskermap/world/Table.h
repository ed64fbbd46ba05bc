#pragma once
#include <Eigen/Core>
#include <whiskermap/world/ObjectClass.h>
#include <whiskermap/world/Obstacle.h>

#include <array>

namespace whiskermap::world
{
/** A ground-truth four-legged object (a table, or a desk, chair, ... by its class): the paper's T(x_T, y_T, theta_T, w_T^L, tau_T) with its
 *  size. Leg centres sit at (+-length/2, +-width/2) in the table frame; legs are squares of
 *  side leg_width aligned with the table. Same table under a 180 degree turn. */
struct Table
{
	double x = 0, y = 0;  ///< centre, metres
	double yaw = 0;  ///< radians
	double length = 0;  ///< leg-centre spacing along the table's x axis, metres
	double width = 0;  ///< leg-centre spacing along the table's y axis, metres
	double leg_width = 0;  ///< side of the square legs, metres
	double texture = 0;  ///< in (0, 1)
	ObjectClass object_class{};  ///< ground-truth class label, default "table" (initialiser: no warning on {x, y, ...})

	/** Centre of leg k (0: +x+y, 1: -x+y, 2: -x-y, 3: +x-y, counter-clockwise). */
	Eigen::Vector2d legCentre(int k) const;
	/** The square of leg k as a solid obstacle tagged with table index `self`. */
	Obstacle leg(int k, int self) const;
	/** The whole outer footprint (legs included), for overlap and arena checks. */
	Obstacle footprint() const;
};
}  // namespace whiskermap::world
