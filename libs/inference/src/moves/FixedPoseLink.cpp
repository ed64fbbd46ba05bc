#include <whiskermap/inference/moves/FixedPoseLink.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

std::optional<Proposal> FixedPoseLink::propose(MoveContext& ctx)
{
	const model::Blackboard& bb = ctx.bb;
	const size_t n = bb.shapelets().size(), legs = bb.legCount(), s = ctx.rng.pick(n);
	if (legs == 0) return std::nullopt;
	const Id from = bb.shapeletParent(s);
	// The others of (legs, none): none first (when s has a leg), then the legs but s's.
	size_t k = ctx.rng.pick(legs);
	Id to = NONE;
	if (from == NONE || k-- > 0)
		for (Id id = 0; id < bb.legIdBound(); id++)
			if (bb.hasLeg(id) && id != from && k-- == 0)
			{
				to = id;
				break;
			}
	if (from != NONE && bb.shapeletsOf(from).size() == 1 && bb.evidence(from).empty())
		return std::nullopt;
	m_shapelet = s, m_to = to;
	Proposal p{Move::Child, model::logShapeletLinkGain(bb, s, to) - model::logShapeletLinkGain(bb, s, from)};
	p.logForward = p.logReverse = -std::log(static_cast<double>(n)) - std::log(static_cast<double>(legs));
	return p;
}

void FixedPoseLink::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) ctx.bb.setShapeletParent(m_shapelet, m_to);
}
}  // namespace whiskermap::inference::moves
