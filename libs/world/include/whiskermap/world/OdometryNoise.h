#pragma once
#include <mrpt/obs/CActionRobotMovement2D.h>

#include <string>

namespace whiskermap::world
{
/** How a simulated robot's odometry errs, and the MRPT motion model its actions carry.
 *  Read from an odometry .ini (config/odometry/: exact, default, poor; format in
 *  doc/formats.md, the noise model in doc/sensor-model.md).
 *
 *  Each step's error is drawn from MRPT's own Gaussian odometry model
 *  (CActionRobotMovement2D, `mmGaussian`) with these coefficients, around the true increment
 *  whose translation is scaled by (1 + scale_bias). */
struct OdometryNoise
{
	double translation_noise = 0;  ///< translation std-dev per metre moved (MRPT a1), m/m
	double translation_noise_per_turn = 0;  ///< translation std-dev per radian turned (a2), m/rad
	double rotation_noise = 0;  ///< heading std-dev per metre moved (a3), rad/m
	double rotation_noise_per_turn = 0;  ///< heading std-dev per radian turned (a4), rad/rad
	double scale_bias = 0;  ///< recorded translation = (1 + scale_bias) x true translation

	/** The Gaussian model written into each CActionRobotMovement2D: the file's
	 *  [motion_model] section, or MRPT's defaults when it has none. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel;

	/** True when the odometry is the true path (every noise term and the bias zero). */
	bool exact() const;

	/** These noise coefficients as MRPT motion-model options (no floors): the model the
	 *  errors are drawn from. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions noiseModel() const;

	/** `nameOrPath`: a preset name (exact, default, poor) or a path to an odometry .ini.
	 *  Throws core::Error naming the file, section and key of a bad value. */
	static OdometryNoise load(const std::string& nameOrPath);
};
}  // namespace whiskermap::world
