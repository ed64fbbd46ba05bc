#pragma once
#include <whiskermap/world/Wall.h>
#include <whiskermap/world/World.h>

#include <utility>
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
	/** Parts of a wall's centre line: [lo, hi] of the distance t from (x0, y0), sorted and
	 *  disjoint when merged. */
	using Interval = std::pair<double, double>;
	using Intervals = std::vector<Interval>;

	double true_length_m = 0, estimated_length_m = 0;
	double true_covered_m = 0, estimated_covered_m = 0;
	double recall = 1;  ///< true_covered / true_length (1 when there is no true wall)
	double precision = 1;  ///< estimated_covered / estimated_length (1 when nothing was estimated)
	double gate_m = 0;
	/** With the touched parts of the true walls (TouchedWalls): their length, the part of it
	 *  covered by estimated walls, and recall_touched = touched_covered / touched_length (1
	 *  when nothing was touched): issue 11's recall "of the wall length the whiskers touched". */
	bool touched_known = false;
	double touched_length_m = 0, touched_covered_m = 0, recall_touched = 1;

	/** `touched`, when given, holds for each true wall (same order) its touched parts. */
	static WallEvaluation compute(
		const std::vector<world::Wall>& truth, const std::vector<world::Wall>& estimated, double gate,
		double gateYawDeg, const std::vector<Intervals>* touched = nullptr);

	/** The true walls of a world: its interior walls, then the arena's four edges (as walls
	 *  whose centre line is the edge). */
	static std::vector<world::Wall> trueWalls(const world::World& w);

	/** The length of `wall`'s centre line within `gate` of some wall of `others` of a
	 *  direction within `gateYawDeg` (modulo 180). */
	static double coveredLength(
		const world::Wall& wall, const std::vector<world::Wall>& others, double gate, double gateYawDeg);
	/** The same part as merged intervals of `wall`'s centre line. */
	static Intervals coveredIntervals(
		const world::Wall& wall, const std::vector<world::Wall>& others, double gate, double gateYawDeg);

	/** Total length of merged intervals, and of the intersection of two merged sets. */
	static double length(const Intervals& a);
	static double overlap(const Intervals& a, const Intervals& b);
	/** Adds [lo, hi] to merged intervals `a`, keeping them sorted and disjoint. */
	static void unite(Intervals& a, double lo, double hi);
};
}  // namespace whiskermap::eval
