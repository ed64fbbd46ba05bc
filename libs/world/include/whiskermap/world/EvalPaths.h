#pragma once
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/World.h>

#include <optional>
#include <vector>

namespace whiskermap::world
{
/** The robot paths of the evaluation worlds (doc/eval-worlds.md). Every pose they return is
 *  free: the robot body overlaps no leg and no wall (WhiskerSimulator::poseIsFree). */
struct EvalPaths
{
	/** The paper grid (Trajectory::paperGrid, n x n positions x 4 headings) without its
	 *  blocked poses; `dropped` (if given) receives how many were left out. */
	static std::vector<mrpt::poses::CPose2D> freeGrid(
		const World& world, const Robot& robot, int n, size_t* dropped = nullptr);

	/** True when the free positions of the n x n grid form one connected set under moves
	 *  between 4-neighbours along which the body stays free (every table can be reached). */
	static bool gridConnected(const World& world, const Robot& robot, int n);

	/** A sparse path: poses that each touch one leg of one table (and perhaps walls),
	 *  `visitsPerLeg` times on `legsPerTable` legs of every table, interleaved over the
	 *  tables, with wall-only poses inserted wherever needed so that no `window` consecutive
	 *  contacts ever hold two legs of one table. Nothing when some table offers fewer than
	 *  two legs that can be touched alone (the caller tries another layout). */
	static std::optional<std::vector<mrpt::poses::CPose2D>> sparse(
		const World& world, const Robot& robot, size_t window, int legsPerTable, int visitsPerLeg,
		mrpt::random::CRandomGenerator& rng);
};
}  // namespace whiskermap::world
