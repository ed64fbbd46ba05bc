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
 *  Under stochastic refits (MoveContext::stochasticRefits: reversible_jump at finite beta)
 *  both are exact: the birth draws the fitted table about its fit (MoveContext::drawnTable)
 *  and its logForward is the probability of the drawn table's cell with those legs, summed
 *  over the candidates that adopt the same legs; the death's logReverse is that probability
 *  for the birth from the table's canonical leg (its leg of least id) on the board after the
 *  death, and a birth from another leg declares no reverse (doc/sampler.md, "Cells, not
 *  densities").
 *  Broad proposals: the 8 single-leg tables per class only, drawn uniformly, not fitted.
 *  Completed (`complete`, the random scan's second pair, doc/sampler.md "Random scan of the
 *  library's moves"): the birth also invents a leg exactly at each corner its adopted legs
 *  leave empty (as birthAtCorner would), and the death takes those invented legs with the
 *  table; its reverse exists when every corner holds a leg and each leg that explains nothing
 *  stands exactly at a corner no other leg holds. A table and its mirror image, each with its
 *  invented legs, are then two moves apart instead of five. */
class TableBirthDeath
{
   public:
	explicit TableBirthDeath(const model::ModelParams& p, bool complete = false) : m_backup(p), m_complete(complete) {}

	Proposal birth(MoveContext& ctx, model::Id l);
	/** The birth of table `chosen` for leg l as birth() makes it once drawn (fitted to the
	 *  legs it adopts, adopting anew), with logForward = 0: SlidingTableBirth's first step. */
	Proposal birthOf(MoveContext& ctx, model::Id l, model::Table chosen);
	Proposal death(MoveContext& ctx, model::Id t);
	/** The death of t and a birth from its canonical leg in one move, completed on a completed
	 *  TableBirthDeath (the random scan's table switch: a table to its mirror image, or to another corner
	 *  assignment, without passing through "no table", which the posterior all but rules
	 *  out). Proposed (else nullopt, board unchanged) under stochastic refits when the death's
	 *  reverse exists and the birth adopts exactly t's legs that explain data; logForward and
	 *  logReverse: the birth's probability of the new and of the old table's cell, on the
	 *  board without either. Its own reverse. */
	std::optional<Proposal> rebirth(MoveContext& ctx, model::Id t);
	void finish(MoveContext& ctx, bool accepted);

   private:
	/** True if a leg of `table` not in `except` explains a shapelet. */
	static bool hasSupportedLeg(const model::Blackboard& bb, model::Id table, const std::vector<model::Id>& except);
	/** Draws a candidate table for leg l (weights ADOPT_WEIGHT^n); `logProbability` gets
	 *  the log of its probability. */
	model::Table drawCandidate(MoveContext& ctx, model::Id l, double& logProbability);
	/** Fills m_tables and m_weights with leg l's candidates and their weights; returns their sum. */
	double weighCandidates(const MoveContext& ctx, model::Id l);
	/** What the birth makes of candidate `chosen` for leg l on the board as it is: the table
	 *  fitted to the legs it adopts (returned) and the legs it then adopts, l last (`adopted`).
	 *  Changes nothing on the board. */
	model::Table outcome(const MoveContext& ctx, model::Id l, model::Table chosen, std::vector<model::Id>& adopted);
	/** Adds table `chosen` adopting m_candidates, with the exact change of logJoint. */
	Proposal place(MoveContext& ctx, const model::Table& chosen);
	/** log of the probability, per eq. 19 cell, that the stochastic birth from leg l (its
	 *  candidates in m_tables, m_weights) proposes `table` adopting exactly `legs` (sorted). */
	double logDrawnBirth(const MoveContext& ctx, model::Id l, const model::Table& table, const std::vector<model::Id>& legs);

	/** True if every corner of table t holds a leg and each of its legs that explains
	 *  nothing stands exactly where a completed birth invents it, alone at its corner. */
	bool invented(const MoveContext& ctx, model::Id t) const;
	/** The completed birth's legs at the empty corners of m_table; adds their eq. 20 log-odds
	 *  to `logTarget`. */
	void invent(MoveContext& ctx, double& logTarget);

	model::Blackboard m_backup;  ///< the board before a move that removes tables, to undo it
	bool m_complete = false;
	std::vector<model::Id> m_invented;  ///< legs the completed birth invented
	std::vector<model::Id> m_resized;  ///< adopted legs refitted at the table's leg width
	bool m_restore = false;  ///< a rejected move restores m_backup (else undoes the birth)
	model::Id m_table = model::NONE;  ///< the table born (NONE after a death)
	std::vector<model::Id> m_candidates, m_oldParents, m_abandoned, m_orphans;
	std::vector<model::Id> m_legs, m_adopted;  ///< a table's legs (sorted), a candidate's outcome
	std::vector<model::Table> m_tables;
	std::vector<double> m_weights;
	std::vector<const model::Leg*> m_fitLegs;
	std::vector<int> m_fitCorners;
};
}  // namespace whiskermap::inference::moves
