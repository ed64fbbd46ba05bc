#pragma once
#include <mrpt/maps/TMetricMapInitializer.h>
#include <whiskermap/slam/TSlamParams.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/world/Obstacle.h>

#include <string>
#include <vector>

namespace whiskermap::cli
{
/** whisker-slam's smoothing of the best particle's path (doc/slam.md, "Smoothing the path").
 *  The constructor reads the first `sweeps` sweeps of the rawlog for their odometry and
 *  contacts; each odometry increment's covariance is the one the particles moved with
 *  (TSlamParams::motionModel, through MRPT's CActionRobotMovement2D). Memory: the contacts
 *  and the factors, linear in the sweeps. */
class SlamSmoothing
{
   public:
	SlamSmoothing(const std::string& rawlog, size_t sweeps, const slam::TSlamParams& slam);

	/** Smooths `path` against `solids` (the best particle's mapped legs and walls); then, for
	 *  each further pass (TSmoothParams::passes), maps the sweeps afresh at the smoothed path
	 *  (a map of `maps`) and smooths again from it against that map's solids. The result is
	 *  the last pass's, with costBefore at `path` (the first pass's) and the rounds and
	 *  iterations of all passes. */
	smooth::PathSmoother::TResult run(
		std::vector<Eigen::Vector3d> path, std::vector<world::Obstacle> solids, const smooth::TSmoothParams& params,
		const mrpt::maps::TSetOfMetricMapInitializers& maps) const;

   private:
	std::string m_rawlog;
	smooth::PathSmoother::TInput m_input;  ///< without path and solids
};
}  // namespace whiskermap::cli
