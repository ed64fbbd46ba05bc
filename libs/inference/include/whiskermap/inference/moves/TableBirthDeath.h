#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>
#include <vector>

namespace whiskermap::inference::moves
{
/** Birth and death of a table (doc/sampler.md, "Moves"):
 *  - birth(l), Q(pa(L) | L): a table of the known size with leg l at a corner (8 candidates
 *    from l's yaw, plus the tables fitted to l and another leg at a corner distance), drawn
 *    with weight ADOPT_WEIGHT^n (n: the other legs it would adopt), fitted to the legs it
 *    adopts (fitTable), adopting them in the same move; old tables left without a supported
 *    leg are removed with it. logForward = log of the candidate's probability (the fit is
 *    deterministic). Its reverse is death of the new table when the adopted legs were free
 *    and explain data and nothing was removed (logReverse = 0); otherwise none (-inf);
 *  - death(t): removes t and its legs that explain nothing (logForward = 0). logReverse =
 *    -inf: the birth proposes fitted poses only, so it proposes a given table with density 0
 *    in general (an approximation: exact unless t's pose is itself such a fit).
 *  Broad proposals: the 8 single-leg tables per class only, drawn uniformly, not fitted. */
class TableBirthDeath
{
   public:
	explicit TableBirthDeath(const model::ModelParams& p) : m_backup(p) {}

	Proposal birth(MoveContext& ctx, model::Id l);
	/** The birth of table `chosen` for leg l as birth() makes it once drawn (fitted to the
	 *  legs it adopts, adopting anew), with logForward = 0: SlidingTableBirth's first step. */
	Proposal birthOf(MoveContext& ctx, model::Id l, model::Table chosen);
	Proposal death(MoveContext& ctx, model::Id t);
	void finish(MoveContext& ctx, bool accepted);

   private:
	/** True if a leg of `table` not in `except` explains a shapelet. */
	static bool hasSupportedLeg(const model::Blackboard& bb, model::Id table, const std::vector<model::Id>& except);
	/** Draws a candidate table for leg l (weights ADOPT_WEIGHT^n); `logProbability` gets
	 *  the log of its probability. */
	model::Table drawCandidate(MoveContext& ctx, model::Id l, double& logProbability);

	model::Blackboard m_backup;  ///< the board before a move that removes tables, to undo it
	std::vector<model::Id> m_resized;  ///< adopted legs refitted at the table's leg width
	bool m_restore = false;  ///< a rejected move restores m_backup (else undoes the birth)
	model::Id m_table = model::NONE;  ///< the table born (NONE after a death)
	std::vector<model::Id> m_candidates, m_oldParents, m_abandoned, m_orphans;
	std::vector<model::Table> m_tables;
	std::vector<double> m_weights;
	std::vector<const model::Leg*> m_fitLegs;
	std::vector<int> m_fitCorners;
};
}  // namespace whiskermap::inference::moves
