#pragma once
#include <Eigen/Core>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/smooth/TSmoothParams.h>
#include <whiskermap/world/Obstacle.h>

#include <vector>

namespace whiskermap::smooth
{
/** Least-squares smoothing of a SLAM path against its map (doc/slam.md, "Smoothing the path").
 *
 *  A particle filter's best particle is one draw from the posterior over paths: where the
 *  sweeps say nothing (along a row with no contact), it wanders with the motion model's
 *  random walk, and its map with it. The smoother finds the most probable path and map
 *  shifts instead: the path's poses (the first fixed: the known start) and a shift per
 *  solid group (each leg alone, the pieces of one straight wall together: WallLines) minimise
 *    sum |odometry residuals|^2 (eq. S2) + sum huber(contact residuals) (eq. S3)
 *      + sum |same-solid residuals|^2 (eqs. S4, S5) + sum |d / solid_sigma|^2
 *      [+ sum (table-shape residuals)^2 (eq. S7, TableShapeFactor; only with table_sigma > 0)],
 *  by Levenberg-Marquardt on the sparse normal equations. Contacts are tied to faces of the
 *  map's solids (ContactFactor::associate) at the start of each round, from the current
 *  estimate; a contact near no face is left out (it belongs to nothing the map holds). Legs
 *  the map holds twice (DuplicateLegs: a table mapped again after the path drifted) are held
 *  to one place, and walls it holds twice (DuplicateWalls) to one line (SameSolidFactor),
 *  which closes the loop the particle left open; each table or wall mapped twice is held only
 *  if the solution holding it costs no more than the one leaving it apart (eq. S6); one left
 *  apart from the start is tried again with the stretch of path that mapped one copy moved onto
 *  the other (eq. S9, ShiftedStretch), a jump small steps cannot make. Stretches that stray
 *  from their odometry are solved again from it (eq. S8, OdometryBridge). Odometry
 *  told exact (every increment's covariance zero) leaves nothing to estimate: the path is the
 *  odometry's chain from the start. */
class PathSmoother
{
   public:
	struct TInput
	{
		std::vector<Eigen::Vector3d> path;  ///< the estimate to start from, one pose (x, y, yaw) per sweep
		std::vector<Eigen::Vector3d> increments;  ///< odometry from sweep i-1 to i in i-1's frame; [0] unused
		std::vector<Eigen::Matrix3d> covariances;  ///< each increment's motion-model covariance; [0] unused
		std::vector<baseline::Contact> contacts;  ///< robot frame; `sweep` indexes the path
		std::vector<world::Obstacle> solids;  ///< the map's legs and walls (table < 0: a wall)
	};
	struct TResult
	{
		std::vector<Eigen::Vector3d> path;
		std::vector<Eigen::Vector2d> shifts;  ///< per group
		std::vector<size_t> groupOf;  ///< per solid
		size_t duplicates = 0;  ///< pairs of legs held to one place (eq. S4; DuplicateLegs)
		size_t duplicatesApart = 0;  ///< pairs found but left apart: holding them cost more (eq. S6)
		size_t duplicateWalls = 0;  ///< pairs of wall groups held to one line (eq. S5; DuplicateWalls)
		size_t duplicateWallsApart = 0;  ///< wall pairs found but left apart (eq. S6)
		size_t stretches = 0;  ///< pairs held only once the stretch that mapped a copy moved onto the other (eq. S9; ShiftedStretch)
		size_t stretchesTried = 0;  ///< of such moves tried (up to two per pair set left apart from the start)
		size_t bridges = 0;  ///< stray stretches solved again from the odometry and kept (eq. S8; OdometryBridge)
		size_t bridgesTried = 0;  ///< of those tried
		double strayMax = 0;  ///< the result's largest m over a window of bridge_window sweeps (eq. S8)
		size_t tied = 0;  ///< contacts tied to a face in the last round (of contacts.size())
		double costBefore = 0, costAfter = 0;  ///< the objective at the start path (first round's ties) and at the end
		unsigned rounds = 0, iterations = 0;
	};

	/** Throws core::Error on inconsistent input (sizes, a contact's sweep out of range). */
	static TResult run(const TInput& in, const TSmoothParams& params);
};
}  // namespace whiskermap::smooth
