#pragma once

namespace whiskermap::obs
{
/** Standard deviations of the i.i.d. zero-mean Gaussian reading noise (paper eqs. 1-3). */
struct TSensorNoise
{
	double sigma_r = 0;  ///< radial distance along the whisker, metres
	double sigma_phi = 0;  ///< surface-normal angle, radians
	double sigma_tau = 0;  ///< texture, unitless in [0, 1]
};
}  // namespace whiskermap::obs
