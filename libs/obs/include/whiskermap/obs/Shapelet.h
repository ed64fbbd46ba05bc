#pragma once

namespace whiskermap::obs
{
/** A contact in world coordinates: the paper's S(x_S, y_S, theta_S, tau_S) (section 2).
 *  Made from one whisker reading and the robot pose at the time of the sweep. */
struct Shapelet
{
	double x = 0;  ///< contact position, metres (world frame)
	double y = 0;
	double normal = 0;  ///< outward surface-normal angle, radians in (-pi, pi] (world frame)
	double texture = 0;  ///< surface texture in [0, 1]
	int whisker = -1;  ///< index of the whisker that made it, within its sweep
	/** Unit direction of the whisker's shaft at the contact, pivot to contact (world frame),
	 *  or (0, 0) when unknown. The reading's noise lies along it (doc/model.md, eq. 7). */
	double shaft_x = 0;
	double shaft_y = 0;

	bool hasShaft() const { return shaft_x != 0 || shaft_y != 0; }
};
}  // namespace whiskermap::obs
