#pragma once
#include <mrpt/maps/TMetricMapInitializer.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/slam/TSlamParams.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/world/Obstacle.h>

#include <string>
#include <vector>

namespace whiskermap::cli
{
/** whisker-slam's smoothing of the best particle's path (doc/slam.md, "Smoothing the path").
 *  It reads the sweeps' odometry and contacts from the rawlog when it runs, after the filter,
 *  so the filter holds no copy of them and its memory does not grow with the sweeps; each
 *  odometry increment's covariance is the one the particles moved with
 *  (TSlamParams::motionModel, through MRPT's CActionRobotMovement2D). Memory while it runs:
 *  the contacts and the factors, linear in the sweeps. */
class SlamSmoothing
{
   public:
	/** `rawlog`: the filter's input, read again by run(). */
	SlamSmoothing(const std::string& rawlog, const slam::TSlamParams& slam) : m_rawlog(rawlog), m_slam(slam) {}

	/** Smooths `path` (one pose per sweep of the rawlog's first path.size(); fewer sweeps
	 *  there: core::Error naming the rawlog) against `solids` (the best particle's mapped
	 *  legs and walls, or those of a map rebuilt at its path: solidsAt); then, for each
	 *  further pass (TSmoothParams::passes), maps the sweeps afresh at the smoothed path (a
	 *  map of `maps`) and smooths again from it against that map's solids. The result is the last pass's, with costBefore at `path` (the first
	 *  pass's) and the rounds and iterations of all passes. */
	smooth::PathSmoother::TResult run(
		std::vector<Eigen::Vector3d> path, std::vector<world::Obstacle> solids, const smooth::TSmoothParams& params,
		const mrpt::maps::TSetOfMetricMapInitializers& maps) const;

	/** The solids of a map of `maps` built by inserting the rawlog's first path.size() sweeps
	 *  at `path`'s poses. */
	std::vector<world::Obstacle> solidsAt(
		const std::vector<Eigen::Vector3d>& path, const mrpt::maps::TSetOfMetricMapInitializers& maps) const;

	/** The error for a rawlog read again after the filter that holds `found` sweeps where the
	 *  filter read `read` (the file changed during the run). */
	static core::Error shorter(const std::string& rawlog, size_t found, size_t read);

   private:
	/** The odometry increments, their covariances and the contacts of the rawlog's first
	 *  `sweeps` sweeps (no path, no solids). Throws core::Error naming the rawlog when it
	 *  holds fewer (changed since the filter read it) or is damaged. */
	smooth::PathSmoother::TInput read(size_t sweeps) const;

	std::string m_rawlog;
	slam::TSlamParams m_slam;
};
}  // namespace whiskermap::cli
