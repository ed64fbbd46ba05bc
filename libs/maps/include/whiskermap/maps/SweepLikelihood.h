#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/world/Obstacle.h>

#include <vector>

namespace whiskermap::maps
{
/** Likelihood of a whisker sweep taken at a robot pose, given mapped solids: each whisker
 *  is cast against them with the simulator's exact geometry (world::WhiskerContact), then
 *  - touched, and the map predicts a touch: a robust Gaussian on the distance d between the
 *    observed and predicted contact points and the difference a between their surface
 *    normals, log((1 - p_unexplained) exp(-d^2 / 2 sigma_contact^2 - a^2 / 2 sigma_normal^2) + p_unexplained);
 *  - touched, the map predicts none: log(p_unexplained) (walls, unmapped objects);
 *  - untouched, the map predicts a touch: log(p_miss) (negative evidence);
 *  - untouched, none predicted: 0.
 *  Unnormalised: compare values for the same sweep at different poses (as particle filters do). */
struct SweepLikelihood
{
	struct TOptions
	{
		double sigma_contact = 0.03;  ///< metres
		double sigma_normal = 0.35;  ///< radians (20 degrees)
		double p_unexplained = 0.2;
		double p_miss = 0.05;
	};

	static double logLikelihood(
		const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& robotPose,
		const std::vector<world::Obstacle>& solids, const TOptions& opts);
};
}  // namespace whiskermap::maps
