#pragma once
#include <mrpt/bayes/CParticleFilter.h>
#include <whiskermap/world/OdometryNoise.h>

#include <cstdint>
#include <string>

namespace whiskermap::slam
{
/** whisker-slam's settings: the [slam] section of config/whisker-slam.ini (doc/slam.md).
 *  Read strictly: unknown keys and sections are errors naming the file. */
struct TSlamParams
{
	unsigned particles = 30;  ///< particle count (each holds a whole map)
	uint64_t seed = 1;  ///< seeds MRPT's global random generator (motion samples, resampling)
	std::string map_config;  ///< the CMultiMetricMap .ini of every particle's map (resolved path)
	world::OdometryNoise motion;  ///< odometry preset whose matched Gaussian model moves the particles
	double motion_noise_scale = 1;  ///< multiplies the motion model's std-devs (a1..a4)
	unsigned proposal_samples = 1;  ///< motion samples per particle and step (SampledProposal; 1: MRPT's standard proposal)
	/** Sweeps every particle's map anneals together (its insertOpts batch_sweeps, overridden
	 *  for the particles; 0: the map config's own). */
	unsigned batch_sweeps = 0;
	/** Every particle's map holds walls, each along wall_axis or at right angles to it
	 *  (model::ModelParams::manhattan_walls; overrides the map config's walls, manhattan_walls
	 *  and wall_axis_deg); off: the map config's own. */
	bool manhattan_walls = false;
	double wall_axis = 0;  ///< radians (key wall_axis_deg, degrees in [-90, 90])
	/** Every particle's likelihood lengthens its mapped walls by this much at each end (the
	 *  map's likelihoodOpts wall_extension, overridden for the particles; 0: the map config's own). */
	double wall_extension = 0;
	/** Every particle's map merges legs that come within this distance (m) of each other (its
	 *  insertOpts leg_merge_gap, overridden for the particles only: the maps built after the
	 *  filter keep the map config's own, so the smoother finds the legs mapped twice; 0: the
	 *  map config's own). */
	double leg_merge_gap = 0;
	/** The map written (not the particles' nor the smoother's: eq. S4 needs the tables mapped
	 *  twice) maps no two tables that overlap or touch (its likelihoodOpts disjoint_tables);
	 *  off: the map config's own. */
	bool disjoint_tables = false;
	double resample_ess = 0.5;  ///< resample when the normalised effective sample size drops below this
	mrpt::bayes::CParticleFilter::TParticleResamplingAlgorithm resampling =
		mrpt::bayes::CParticleFilter::prSystematic;

	/** The motion model of one odometry increment: `motion`'s matched Gaussian model with its
	 *  a1..a4 times motion_noise_scale (what moves the particles). */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel(const mrpt::poses::CPose2D& increment) const;

	/** The motion model moves every particle by the odometry exactly (exact odometry and no
	 *  [motion_model] floors): the particles then follow one path, and their maps, which
	 *  insert the same sweeps at the same poses with the same seeds, are one map. */
	bool exactMotion() const { return motion.exact() && motion.min_std_xy == 0 && motion.min_std_phi == 0; }
	/** The particles the filter runs: `particles`, or one when exactMotion() (the others
	 *  would repeat it, draw for draw). */
	unsigned filterParticles() const { return exactMotion() ? 1 : particles; }

	/** Reads `path`. Relative `map_config` and `odometry_model` files are looked up next to
	 *  it first, then as shipped presets (config/, config/odometry/). */
	static TSlamParams load(const std::string& path);
};
}  // namespace whiskermap::slam
