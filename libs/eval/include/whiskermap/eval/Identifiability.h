#pragma once
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/World.h>

#include <bitset>
#include <cstdint>
#include <unordered_map>
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
	/** The same from the largest sigma_r of a log (RawlogReader::Summary::maxSigmaR). */
	static double gateFor(double maxSigmaR) { return 3 * maxSigmaR + 0.01; }

	static Identifiability of(
		const world::World& world, const std::vector<obs::RawlogReader::Sweep>& sweeps,
		double gate);

	/** Sweeps given one at a time: memory bounded by the world, not the log. Tables are
	 *  indexed on a grid, so a contact costs the same however many tables. */
	class Accumulator
	{
	   public:
		Accumulator(const world::World& world, double gate);
		void add(const obs::RawlogReader::Sweep& sweep);
		Identifiability result() const;

	   private:
		const world::World& m_world;
		double m_gate, m_cell;
		std::unordered_map<int64_t, std::vector<uint32_t>> m_grid;  ///< cell -> tables near it
		std::vector<std::bitset<4>> m_touched;
	};

	/** Matched identifiable tables / identifiable tables (1 when there are none), from an
	 *  evaluation of a map against all of `world`'s tables. */
	double recall(const MapEvaluation& e) const;
};
}  // namespace whiskermap::eval
