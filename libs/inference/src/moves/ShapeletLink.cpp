#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
using model::NONE;

namespace
{
constexpr double NO_REVERSE = -std::numeric_limits<double>::infinity();
}

Proposal ShapeletLink::link(MoveContext& ctx, size_t s, model::Id l, Move kind)
{
	model::Blackboard& bb = ctx.bb;
	const model::Id from = bb.shapeletParent(s);
	const bool stochastic = ctx.stochasticRefits();
	// The reverse refits `from` with s (as it is now) and leaves l where the refit put it.
	const bool fromAtFit = !stochastic && from != NONE && ctx.atFit(from);
	m_shapelet = s, m_from = from, m_to = l, m_old = bb.leg(l);
	if (from != NONE) m_oldFrom = bb.leg(from);
	Proposal p{kind, model::logShapeletLinkGain(bb, s, l) - model::logShapeletLinkGain(bb, s, from)};
	bb.setShapeletParent(s, l);
	m_drop = from != NONE && bb.leg(from).parent == NONE && !bb.explains(from);
	if (!stochastic)
	{
		ctx.refitInPlace(l, p.logTarget);
		if (m_drop) p.logTarget -= model::logOddsLeg(bb, from);
		const model::Leg& now = bb.leg(l);
		const bool stays = now.x == m_old.x && now.y == m_old.y && now.theta == m_old.theta && now.texture == m_old.texture;
		p.logReverse = fromAtFit && stays && !m_drop ? 0 : NO_REVERSE;
		return p;
	}
	// Stochastic refits: l (with s) and the leg s left (without it) are drawn about their fits;
	// the reverse links s back and draws each about its fit then. Leaving a leg that is then
	// dropped, or coming from no leg, has no reverse link (the reverse of a drop is a split).
	const bool drewTo = ctx.drawRefit(l, p.logTarget, p.logForward);
	const bool drewFrom = from == NONE || m_drop || ctx.drawRefit(from, p.logTarget, p.logForward);
	if (m_drop) p.logTarget -= model::logOddsLeg(bb, from);
	if (from == NONE || m_drop || !drewTo || !drewFrom)
	{
		p.logReverse = NO_REVERSE;
		return p;
	}
	bb.setShapeletParent(s, from);
	p.logReverse = ctx.logRefitTo(from, m_oldFrom) + ctx.logRefitTo(l, m_old);
	bb.setShapeletParent(s, l);
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
	if (m_from != NONE) ctx.bb.setLeg(m_from, m_oldFrom);
	ctx.bb.setShapeletParent(m_shapelet, m_from);
}
}  // namespace whiskermap::inference::moves
