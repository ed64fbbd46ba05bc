#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Refit of a leg (doc/sampler.md, "Moves"): the closed-form pose for its contacts and its
 *  parent's corner (PoseFit.h). Deterministic (logForward = 0) and idempotent, so no move
 *  proposes the old pose back: logReverse = -inf unless the pose did not change (0). The
 *  polish uses it as a greedy improvement, where densities play no part. With broad
 *  proposals it is a symmetric random-walk step (MoveContext::randomWalk; logReverse = 0).
 *  Under the reversible-jump acceptance at finite beta it is stochastic, so that it has a
 *  reverse (MoveContext::drawRefit): logForward is the density of the new pose about the fit
 *  from the old board, logReverse that of the old pose about the fit from the new board. */
class LegRefit
{
   public:
	/** nullopt (nothing proposed) if the fit leaves a contact or the corner outside the gate. */
	std::optional<Proposal> propose(MoveContext& ctx, model::Id l);
	void finish(MoveContext& ctx, bool accepted);

	/** 0 if `before` and `after` have the same pose and texture, else -inf: the reverse
	 *  density of a deterministic refit. */
	static double logReverseOfRefit(const model::Leg& before, const model::Leg& after);

   private:
	model::Id m_leg = model::NONE;
	model::Leg m_old;
};
}  // namespace whiskermap::inference::moves
