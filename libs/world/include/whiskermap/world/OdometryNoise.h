#pragma once
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>

#include <string>

namespace whiskermap::world
{
/** How a simulated robot's odometry errs, and the MRPT motion model its actions carry. Read
 *  from an odometry .ini (config/odometry/: exact, default, poor; format in doc/formats.md,
 *  the model in doc/sensor-model.md, "Odometry").
 *
 *  The errors are random walks: over a step that travels d metres and turns dphi radians, the
 *  translation error has std-dev translation_noise sqrt(d) + turn_translation_noise
 *  sqrt(|dphi|) along each axis and the heading error rotation_noise sqrt(d) + turn_noise
 *  sqrt(|dphi|), so the drift over a path does not depend on how finely it is sampled (the
 *  whisk rate); the recorded translation is also scaled by (1 + scale_bias). */
struct OdometryNoise
{
	double translation_noise = 0;  ///< translation std-dev after 1 m travelled, metres
	double rotation_noise = 0;  ///< heading std-dev after 1 m travelled, radians
	double turn_noise = 0;  ///< heading std-dev after 1 rad turned, radians
	double turn_translation_noise = 0;  ///< translation std-dev after 1 rad turned, metres
	double scale_bias = 0;  ///< recorded translation = (1 + scale_bias) x true translation
	/** A [motion_model] section was given: each action carries MRPT's Gaussian model matched
	 *  to its own step (motionModel), with these floors; otherwise MRPT's default model. */
	bool matched_model = false;
	double min_std_xy = 0;  ///< metres
	double min_std_phi = 0;  ///< radians

	/** True when the odometry is the true path (every noise term and the bias zero). */
	bool exact() const;

	/** Std-dev of a step's translation error along each axis (metres) and of its heading
	 *  error (radians): the step travels `d` metres and turns `dphi` radians. */
	double sigmaXY(double d, double dphi) const;
	double sigmaPhi(double d, double dphi) const;

	/** The Gaussian model an action recording `increment` carries. Matched: MRPT's
	 *  std_xy = minStdXY + a1 d + a2 |dphi| and std_phi = minStdPHI + a3 d + a4 |dphi| equal
	 *  min_std_xy + sigmaXY + |scale_bias| d and min_std_phi + sigmaPhi, i.e.
	 *  a1 = translation_noise / sqrt(d) + |scale_bias|, a2 = turn_translation_noise / sqrt(|dphi|),
	 *  a3 = rotation_noise / sqrt(d), a4 = turn_noise / sqrt(|dphi|) (0 when d or dphi is 0).
	 *  Otherwise MRPT's default options. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel(const mrpt::poses::CPose2D& increment) const;

	/** `nameOrPath`: a preset name (exact, default, poor) or a path to an odometry .ini.
	 *  Throws core::Error naming the file, section and key of a bad value. */
	static OdometryNoise load(const std::string& nameOrPath);
};
}  // namespace whiskermap::world
