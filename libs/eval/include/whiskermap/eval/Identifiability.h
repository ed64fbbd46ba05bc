#pragma once
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/World.h>

#include <vector>

namespace whiskermap::eval
{
/** An upper bound on what any mapper could find from a run: a table is identifiable when the
 *  robot touched it on at least two different legs (one leg alone leaves the table's
 *  orientation and extent open). A contact is "on" a leg when its world-frame shapelet lies
 *  within `gate` of the leg square. */
struct Identifiability
{
	std::vector<size_t> tables;  ///< indices (into World::tables) of the identifiable tables
	double gate = 0;  ///< metres, as used

	/** The default gate for these sweeps: 3 sigma_r (largest over the sweeps) + 1 cm. */
	static double defaultGate(const std::vector<obs::RawlogReader::Sweep>& sweeps);

	static Identifiability of(
		const world::World& world, const std::vector<obs::RawlogReader::Sweep>& sweeps,
		double gate);

	/** Matched identifiable tables / identifiable tables (1 when there are none), from an
	 *  evaluation of a map against all of `world`'s tables. */
	double recall(const MapEvaluation& e) const;
};
}  // namespace whiskermap::eval
