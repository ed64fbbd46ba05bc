#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Exchange of one contact between two neighbouring legs (doc/sampler.md, "Moves"): shapelet
 *  s leaves its leg for leg `to`, and both legs refit to their contacts (and corners). A link
 *  (ShapeletLink) refits only the leg it joins, so the leg left behind keeps a pose fitted to
 *  the contact it lost and the link loses; judged with both refits, the contact goes where it
 *  is explained best. Only while something stays on the leg it leaves (a contact or folded
 *  evidence; else it is a merge). Judged on the exact local change of logJoint (eq. 20 of
 *  each leg before and after). Deterministic given (s, to), with no reverse (the refits are
 *  deterministic: logReverse = -inf): the polish's last sweep offers it for every contact of
 *  a leg and every other leg whose perimeter is within the parent gate of it. */
class ContactExchange
{
   public:
	/** nullopt (board unchanged) when s has no leg, `to` is it, or nothing would stay on it. */
	std::optional<Proposal> propose(MoveContext& ctx, size_t s, model::Id to);
	void finish(MoveContext& ctx, bool accepted);

   private:
	size_t m_shapelet = 0;
	model::Id m_from = model::NONE, m_to = model::NONE;
	model::Leg m_oldFrom, m_oldTo;
};
}  // namespace whiskermap::inference::moves
