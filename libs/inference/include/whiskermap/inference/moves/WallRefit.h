#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Refit of a wall's line and extent (doc/sampler.md, "Walls"): the closed-form fit to its
 *  shapelets and folded evidence (fitWall). Deterministic and idempotent, as LegRefit:
 *  logForward = 0, logReverse = -inf unless nothing moved (0). Judged on the change of the
 *  wall's log-odds (eq. 20 for walls: its cell, its contacts, the legs standing in it), which
 *  is the change of logJoint. */
class WallRefit
{
   public:
	std::optional<Proposal> propose(MoveContext& ctx, model::Id w);
	void finish(MoveContext& ctx, bool accepted);

   private:
	model::Id m_wall = model::NONE;
	model::Wall m_old;
};
}  // namespace whiskermap::inference::moves
