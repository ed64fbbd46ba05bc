#pragma once
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/model/LegEvidence.h>

#include <optional>
#include <vector>

namespace whiskermap::inference::moves
{
/** Split and merge of legs (doc/sampler.md, "Moves"), each the other's reverse:
 *  - split(s): contact s leaves its leg (which refits to the rest) for a new free leg placed
 *    as in priming: logForward = the new leg's birth density (LegBirthDeath). The reverse is
 *    the merge of the new leg into the old one, exact (logReverse = 0) when the old leg stood
 *    at its fit (the merge's refit then puts it back), else -inf;
 *  - merge(l, other): every contact (and folded contact) of leg `other` moves to leg l,
 *    `other` is removed and l refits to all its contacts. Deterministic: logForward = 0. The
 *    reverse is the split of other's one contact, exact when `other` was a free leg with one
 *    contact, nothing folded and a birth's width and texture, and l stood at its fit:
 *    logReverse = the birth density of other's pose; else -inf.
 *  Under stochastic refits (MoveContext::stochasticRefits) the refitted leg is drawn about its
 *  fit (its density joins logForward) and the reverse draws it back (its density of the old
 *  pose joins logReverse), so neither needs the old leg at its fit.
 *  Both are judged on the exact local change of logJoint and undone exactly on rejection. */
class SplitMerge
{
   public:
	Proposal split(MoveContext& ctx, size_t s);
	/** Not proposed (nullopt, board unchanged) if `other` explains nothing or l's fit leaves
	 *  the gate. */
	std::optional<Proposal> merge(MoveContext& ctx, model::Id l, model::Id other);
	void finish(MoveContext& ctx, bool accepted);

	/** Fills `out` with the legs other than `l` that explain a shapelet and stand near enough
	 *  for one leg to explain both legs' contacts. */
	static void candidates(const MoveContext& ctx, model::Id l, std::vector<model::Id>& out);

   private:
	void undoMerge(MoveContext& ctx);

	bool m_split = false;
	size_t m_shapelet = 0;
	model::Id m_leg = model::NONE, m_other = model::NONE;  ///< split: from, new; merge: l, other
	model::Leg m_oldLeg, m_oldOther;
	model::LegEvidence m_oldEvidence, m_otherEvidence;
	std::vector<model::Id> m_moved;
};
}  // namespace whiskermap::inference::moves
