#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>
#include <vector>

namespace whiskermap::inference::moves
{
/** A new parent for a leg (doc/sampler.md, "Moves"): uniformly among none (if it has a
 *  parent) and the other tables with a corner within the parent gate of it; poses do not
 *  change. logForward = -log(candidates). Its own reverse, exact: the reparent back to the
 *  old parent, proposed with probability 1 / (candidates from the new parent); -inf when
 *  the old parent's corner is beyond the gate (it is no candidate then). */
class LegReparent
{
   public:
	/** nullopt (nothing proposed) when there is no candidate. */
	std::optional<Proposal> propose(MoveContext& ctx, model::Id l);
	void finish(MoveContext& ctx, bool accepted);

	/** True if a corner of table t is within the parent gate of leg l's centre. */
	static bool withinGate(const MoveContext& ctx, model::Id l, model::Id t);

   private:

	model::Id m_leg = model::NONE, m_to = model::NONE;
	std::vector<model::Id> m_candidates;
};
}  // namespace whiskermap::inference::moves
