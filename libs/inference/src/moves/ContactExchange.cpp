#include <whiskermap/inference/moves/ContactExchange.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
std::optional<Proposal> ContactExchange::propose(MoveContext& ctx, size_t s, model::Id to)
{
	model::Blackboard& bb = ctx.bb;
	const model::Id from = bb.shapeletParent(s);
	if (from == model::NONE || from == to || bb.shapeletsOf(from).size() + !bb.evidence(from).empty() < 2)
		return std::nullopt;
	m_shapelet = s, m_from = from, m_to = to;
	m_oldFrom = bb.leg(from), m_oldTo = bb.leg(to);
	// eq. 12 of s under each leg, then eq. 20 of each leg before and after its refit
	Proposal p{Move::Child, model::logShapeletLinkGain(bb, s, to) - model::logShapeletLinkGain(bb, s, from)};
	bb.setShapeletParent(s, to);
	// Both fits must keep their contacts (and corners) within the gate, as in every move
	if (!ctx.refitInPlace(to, p.logTarget) || !ctx.refitInPlace(from, p.logTarget))
	{
		finish(ctx, false);
		return std::nullopt;
	}
	p.logReverse = -std::numeric_limits<double>::infinity();
	return p;
}

void ContactExchange::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	ctx.bb.setLeg(m_from, m_oldFrom);
	ctx.bb.setLeg(m_to, m_oldTo);
	ctx.bb.setShapeletParent(m_shapelet, m_from);
}
}  // namespace whiskermap::inference::moves
