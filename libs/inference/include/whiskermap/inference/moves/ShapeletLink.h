#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

namespace whiskermap::inference::moves
{
/** Link of a shapelet to a leg (doc/sampler.md, "Moves"): shapelet s moves to leg l (from
 *  its leg, or from none), l refits to its contacts (and corner), and the leg s leaves is
 *  dropped if it is then a free leg explaining nothing (the prune would drop it). Judged on
 *  the exact local change of logJoint. Deterministic given (s, l): logForward = 0. Its own
 *  reverse: linking s back to the leg it left, which refits that leg (not l); exact
 *  (logReverse = 0) when s left a leg that stays and stands at its fit and l's refit did not
 *  move l; otherwise none (-inf; the reverse of a drop is a split). Under stochastic refits
 *  (MoveContext::stochasticRefits) l and the leg s leaves are drawn about their fits
 *  (logForward: both densities) and the reverse exists whenever s left a leg that stays
 *  (logReverse: the densities of both old poses about the fits of the reverse link). */
class ShapeletLink
{
   public:
	Proposal link(MoveContext& ctx, size_t s, model::Id l, Move kind);
	void finish(MoveContext& ctx, bool accepted);

   private:
	size_t m_shapelet = 0;
	model::Id m_from = model::NONE, m_to = model::NONE;
	model::Leg m_old;  ///< leg m_to before its refit
	model::Leg m_oldFrom;  ///< leg m_from before (stochastic refits move it)
	bool m_drop = false;
};
}  // namespace whiskermap::inference::moves
