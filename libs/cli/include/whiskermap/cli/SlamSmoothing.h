#pragma once
#include <mrpt/maps/TMetricMapInitializer.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/slam/TSlamParams.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/world/Obstacle.h>

#include <optional>
#include <string>
#include <vector>

namespace whiskermap::cli
{
/** whisker-slam's smoothing of the best particle's path (doc/slam.md, "Smoothing the path").
 *  add() takes each sweep's odometry and contacts as the filter reads them (no second read
 *  of the rawlog); each odometry increment's covariance is the one the particles moved with
 *  (TSlamParams::motionModel, through MRPT's CActionRobotMovement2D). Memory: the contacts
 *  and the factors, linear in the sweeps. */
class SlamSmoothing
{
   public:
	/** `rawlog`: read again only by the passes after the first (their maps). */
	SlamSmoothing(const std::string& rawlog, const slam::TSlamParams& slam) : m_rawlog(rawlog), m_slam(slam) {}

	/** The next sweep, in rawlog order. */
	void add(const obs::RawlogReader::Sweep& sweep);

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
	slam::TSlamParams m_slam;
	std::optional<mrpt::poses::CPose2D> m_last;  ///< the previous sweep's odometry
	smooth::PathSmoother::TInput m_input;  ///< without path and solids
};
}  // namespace whiskermap::cli
