#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/TSensorNoise.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/WhiskerSimulator.h>
#include <whiskermap/world/World.h>

#include <bitset>
#include <cstdint>
#include <vector>

namespace whiskermap::world
{
/** What a run really touched, from the simulator's per-whisker truth: each contact in rawlog
 *  order (sweep by sweep, whisker by whisker, as CObservationWhiskerContacts::toShapelets
 *  lists them) labelled with its table and leg, or as a wall. Used to check evaluation paths
 *  (doc/eval-worlds.md): which tables are identifiable (touched on >= 2 legs) and how close
 *  together two legs of one table ever come in the contact stream. */
struct TouchAudit
{
	/** One contact's truth; `table` -1 for a wall. */
	struct Label
	{
		int table = -1, leg = -1;
	};

	std::vector<Label> contacts;  ///< every contact of the run, in rawlog order
	std::vector<std::bitset<4>> legsTouched;  ///< per table of the world
	size_t blockedPoses = 0;  ///< poses skipped because the body overlapped an obstacle

	/** Simulates `path` in `world` (blocked poses skipped, as whisker-sim does) and records
	 *  the truth of every contact. */
	static TouchAudit run(
		const World& world, const Robot& robot, const obs::TSensorNoise& noise, uint64_t seed,
		const std::vector<mrpt::poses::CPose2D>& path);

	/** Tables touched on at least two legs (the identifiability bound of doc/evaluation.md). */
	size_t identifiable() const;
	/** Fewest legs touched on any table (0 when some table was never touched). */
	int fewestLegs() const;
	/** The smallest j - i over contacts i < j on two different legs of one table (SIZE_MAX
	 *  when there are none): a window of W consecutive contacts never holds two legs of one
	 *  table exactly when this is >= W. */
	size_t closestCrossLegSpacing() const;
	/** Contacts on a table leg (not on a wall). */
	size_t tableContacts() const;
};
}  // namespace whiskermap::world
