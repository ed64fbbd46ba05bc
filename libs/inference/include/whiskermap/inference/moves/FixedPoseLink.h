#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Link of a shapelet without refit, for the random scan (doc/sampler.md, "Random scan on a
 *  pose grid"): a shapelet s uniformly among all N, then its new leg uniformly among the
 *  others of (the legs, none): as many choices, legs, whatever s's leg. Nothing moves, so it
 *  is its own exact reverse: logForward = logReverse = -log N - log(legs). Not proposed when
 *  s would leave a leg explaining nothing (for a free leg, that is a leg death). */
class FixedPoseLink
{
   public:
	std::optional<Proposal> propose(MoveContext& ctx);
	void finish(MoveContext& ctx, bool accepted);

   private:
	size_t m_shapelet = 0;
	model::Id m_to = model::NONE;
};
}  // namespace whiskermap::inference::moves
