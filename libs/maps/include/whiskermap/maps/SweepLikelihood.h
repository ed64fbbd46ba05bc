#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/model/SweptGrid.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/world/Obstacle.h>

#include <vector>

namespace whiskermap::maps
{
/** Likelihood of a whisker sweep taken at a robot pose, given mapped solids: each whisker
 *  is cast against them with the simulator's exact geometry (world::WhiskerContact), then
 *  - touched, and the map predicts a touch: a robust Gaussian on the distance d between the
 *    observed and predicted contact points and the difference a between their surface
 *    normals, log((1 - p_unexplained) exp(-d^2 / 2 sigma_contact^2 - a^2 / 2 sigma_normal^2) + p_u);
 *  - touched, the map predicts none: log(p_u) (walls, unmapped objects);
 *  - untouched, the map predicts a touch: log(p_miss) (negative evidence);
 *  - untouched, none predicted: 0.
 *  Without a swept grid p_u = p_unexplained. With the map's swept grid (use_swept_grid on), the
 *  grid's evidence joins in (doc/map-plugin.md, "The sweep likelihood", eqs. L1-L5):
 *  p_u = min(1, p_unexplained theta(c) / cell_prior) at the contact's cell c, not above
 *  p_unexplained when the legs predict the contact (L2); each sample of the whisker's swept
 *  boundary adds log((1 - theta) / (1 - cell_prior)) (L3); unexplored boundary samples and
 *  an unexplored robot cell cost log(p_unexplored) (L4, L5).
 *  Unnormalised: compare values for the same sweep at different poses (as particle filters do). */
struct SweepLikelihood
{
	struct TOptions
	{
		double sigma_contact = 0.03;  ///< metres
		double sigma_normal = 0.35;  ///< radians (20 degrees)
		double p_unexplained = 0.2;
		double p_miss = 0.05;
		/** Use the map's swept grid (eqs. L1-L5). Off by default: on a converged filter its
		 *  0.1 m cells blur the legs' 3 cm likelihood (tracking error 0.024 -> 0.064 m); on for
		 *  global localisation (config/pf-global-localization.ini). */
		bool use_swept_grid = false;
		double cell_prior = 0.1;  ///< rho_0: chance a shaft crossing an unexplored cell touches there
		double cell_prior_sweeps = 1;  ///< k: the prior's weight, in sweeps (eq. L1)
		double p_unexplored = 0.05;  ///< chance the robot, or a whisker's sweep, is where the map never explored
	};

	static double logLikelihood(
		const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& robotPose,
		const std::vector<world::Obstacle>& solids, const TOptions& opts, const model::SweptGrid* grid = nullptr);

	/** eq. L1: a cell's posterior chance theta that a shaft crossing it touches there. */
	static double touchChance(const model::SweptGrid::Cell& c, const TOptions& o)
	{
		return (c.touches + o.cell_prior_sweeps * o.cell_prior) / (c.touches + c.passes + o.cell_prior_sweeps);
	}
	/** eqs. L3 and L5: the log-evidence of the boundary of one whisker's swept sector: pivot
	 *  (x, y), shaft `length`, turned from angle `start` to `stop` (world radians), where it
	 *  rests on a contact `stopReach` metres from the pivot (the length when untouched);
	 *  samples in `legCells` (cells holding a mapped leg) are left to the leg term. */
	static double sweptBoundary(
		const model::SweptGrid& grid, double x, double y, double length, double start, double stop, double stopReach,
		const std::vector<std::pair<int32_t, int32_t>>& legCells, const TOptions& o);
};
}  // namespace whiskermap::maps
