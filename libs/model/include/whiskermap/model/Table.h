#pragma once

namespace whiskermap::model
{
/** A table hypothesis T(x_T, y_T, theta_T, w_T^L, tau_T) (paper section 3) of class `cls`.
 *  Its length and width are its class's plus its own offsets (ModelParams::lengthOf(t),
 *  widthOf(t); the offsets stay 0 unless the model key `size_moves` lets the sampler resize
 *  it, eq. 24); legs sit at its four corners (+-length/2, +-width/2) in its own frame. Same
 *  under a 180 degree turn. */
struct Table
{
	double x = 0;  ///< centre, metres (world frame)
	double y = 0;
	double theta = 0;  ///< yaw, radians (period pi)
	double leg_width = 0;  ///< side of its square legs, metres
	double texture = 0;  ///< texture of its legs, in [0, 1]
	int cls = 0;  ///< its class: an index into ModelParams::classes (0 without a catalogue)
	double d_length = 0;  ///< its length (leg-centre spacing along x) minus its class's, metres
	double d_width = 0;  ///< its width minus its class's, metres
};
}  // namespace whiskermap::model
