#pragma once

namespace whiskermap::model
{
/** A table hypothesis T(x_T, y_T, theta_T, w_T^L, tau_T) (paper section 3) of class `cls`.
 *  Its length and width are its class's (ModelParams::lengthOf, widthOf: the strong prior); legs sit at its four corners
 *  (+-length/2, +-width/2) in its own frame. Same under a 180 degree turn. */
struct Table
{
	double x = 0;  ///< centre, metres (world frame)
	double y = 0;
	double theta = 0;  ///< yaw, radians (period pi)
	double leg_width = 0;  ///< side of its square legs, metres
	double texture = 0;  ///< texture of its legs, in [0, 1]
	int cls = 0;  ///< its class: an index into ModelParams::classes (0 without a catalogue)
};
}  // namespace whiskermap::model
