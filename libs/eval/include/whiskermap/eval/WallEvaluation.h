#pragma once
#include <whiskermap/world/Wall.h>
#include <whiskermap/world/World.h>

#include <vector>

namespace whiskermap::eval
{
/** Estimated walls scored against the true ones by length (doc/evaluation.md). A point of a
 *  wall's centre line is covered by another wall when that wall's centre line passes within
 *  `gate` metres of it and the two directions differ by at most `gateYawDeg` (modulo 180).
 *  Recall: the true walls' length covered by estimated walls over their whole length;
 *  precision: the estimated walls' length covered by true walls over theirs. */
struct WallEvaluation
{
	double true_length_m = 0, estimated_length_m = 0;
	double true_covered_m = 0, estimated_covered_m = 0;
	double recall = 1;  ///< true_covered / true_length (1 when there is no true wall)
	double precision = 1;  ///< estimated_covered / estimated_length (1 when nothing was estimated)
	double gate_m = 0;

	static WallEvaluation compute(
		const std::vector<world::Wall>& truth, const std::vector<world::Wall>& estimated, double gate,
		double gateYawDeg);

	/** The true walls of a world: its interior walls, then the arena's four edges (as walls
	 *  whose centre line is the edge). */
	static std::vector<world::Wall> trueWalls(const world::World& w);

	/** The length of `wall`'s centre line within `gate` of some wall of `others` of a
	 *  direction within `gateYawDeg` (modulo 180). */
	static double coveredLength(
		const world::Wall& wall, const std::vector<world::Wall>& others, double gate, double gateYawDeg);
};
}  // namespace whiskermap::eval
