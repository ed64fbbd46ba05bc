#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
using model::NONE;

Proposal ShapeletLink::link(MoveContext& ctx, size_t s, model::Id l, Move kind)
{
	model::Blackboard& bb = ctx.bb;
	const model::Id from = bb.shapeletParent(s);
	// The reverse refits `from` with s (as it is now) and leaves l where the refit put it.
	const bool fromAtFit = from != NONE && ctx.atFit(from);
	m_shapelet = s, m_from = from, m_to = l, m_old = bb.leg(l);
	Proposal p{kind, model::logShapeletLinkGain(bb, s, l) - model::logShapeletLinkGain(bb, s, from)};
	bb.setShapeletParent(s, l);
	ctx.refitInPlace(l, p.logTarget);
	m_drop = from != NONE && bb.leg(from).parent == NONE && !bb.explains(from);
	if (m_drop) p.logTarget -= model::logOddsLeg(bb, from);
	const model::Leg& now = bb.leg(l);
	const bool stays = now.x == m_old.x && now.y == m_old.y && now.theta == m_old.theta && now.texture == m_old.texture;
	p.logReverse = fromAtFit && stays && !m_drop ? 0 : -std::numeric_limits<double>::infinity();
	return p;
}

void ShapeletLink::finish(MoveContext& ctx, bool accepted)
{
	if (accepted)
	{
		if (m_drop) ctx.bb.removeLeg(m_from);
		return;
	}
	ctx.bb.setLeg(m_to, m_old);
	ctx.bb.setShapeletParent(m_shapelet, m_from);
}
}  // namespace whiskermap::inference::moves
