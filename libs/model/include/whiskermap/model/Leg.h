#pragma once
#include <whiskermap/model/Id.h>

namespace whiskermap::model
{
/** A leg hypothesis L(x_L, y_L, theta_L, w_L^x, w_L^y, tau_L, parent) (paper section 3): a
 *  rectangle (square in practice: same under a 90 degree turn) with an explicit parent. */
struct Leg
{
	double x = 0;  ///< centre, metres (world frame)
	double y = 0;
	double theta = 0;  ///< yaw, radians; its faces' outward normals are theta + k*pi/2
	double wx = 0;  ///< extent along its own x axis, metres
	double wy = 0;  ///< extent along its own y axis, metres
	double texture = 0;  ///< in [0, 1]
	Id parent = NONE;  ///< parent table id, or NONE (null cause, eq. 8)
	int corner = -1;  ///< the parent's corner it stands at (argmin of eq. 6), -1 without parent
	bool operator==(const Leg& o) const
	{
		return x == o.x && y == o.y && theta == o.theta && wx == o.wx && wy == o.wy && texture == o.texture &&
			   parent == o.parent && corner == o.corner;
	}
};
}  // namespace whiskermap::model
