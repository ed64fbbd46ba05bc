#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
std::optional<Proposal> LegRefit::propose(MoveContext& ctx, model::Id l)
{
	m_leg = l;
	m_old = ctx.bb.leg(l);
	Proposal p{Move::Refit};
	if (ctx.stochasticRefits())
	{
		if (!ctx.drawRefit(l, p.logTarget, p.logForward)) return std::nullopt;
		p.logReverse = ctx.logRefitTo(l, m_old);
		return p;
	}
	if (!ctx.refitInPlace(l, p.logTarget)) return std::nullopt;
	// A closed-form refit has a reverse only where it leaves the leg; a random-walk step
	// (broad proposals) is symmetric.
	p.logReverse = ctx.broad() ? 0 : logReverseOfRefit(m_old, ctx.bb.leg(l));
	return p;
}

void LegRefit::finish(MoveContext& ctx, bool accepted)
{
	if (!accepted) ctx.bb.setLeg(m_leg, m_old);
}

double LegRefit::logReverseOfRefit(const model::Leg& before, const model::Leg& after)
{
	const bool same = before.x == after.x && before.y == after.y && before.theta == after.theta &&
					  before.texture == after.texture;
	return same ? 0 : -std::numeric_limits<double>::infinity();
}
}  // namespace whiskermap::inference::moves
