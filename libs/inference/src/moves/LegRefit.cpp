#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
std::optional<Proposal> LegRefit::propose(MoveContext& ctx, model::Id l)
{
	m_leg = l;
	m_old = ctx.bb.leg(l);
	Proposal p{Move::Refit};
	if (ctx.sp.acceptance == AcceptanceRule::ReversibleJump && !ctx.greedy() && !ctx.broad())
	{
		const model::Id parent = m_old.parent;
		const model::Table* t = parent == model::NONE ? nullptr : &ctx.bb.table(parent);
		model::Leg fit, back;
		if (!ctx.fittedLeg(l, t, fit)) return std::nullopt;
		model::Leg drawn = fit;
		drawn.x += ctx.sp.leg_position_noise * ctx.rng.gaussian();
		drawn.y += ctx.sp.leg_position_noise * ctx.rng.gaussian();
		drawn.theta += ctx.sp.leg_angle_noise * ctx.rng.gaussian();
		p.logForward = logDrawnAbout(ctx, drawn, fit);
		p.logTarget = -model::logOddsLeg(ctx.bb, l);
		ctx.bb.setLeg(l, drawn);
		p.logTarget += model::logOddsLeg(ctx.bb, l);
		p.logReverse = ctx.fittedLeg(l, t, back) ? logDrawnAbout(ctx, m_old, back) : -std::numeric_limits<double>::infinity();
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

double LegRefit::logDrawnAbout(const MoveContext& ctx, const model::Leg& leg, const model::Leg& fit)
{
	if (leg.texture != fit.texture || leg.wx != fit.wx || leg.wy != fit.wy) return -std::numeric_limits<double>::infinity();
	const auto logGaussian = [](double d, double sigma) {  // zero noise: a point mass at the fit
		if (!(sigma > 0)) return d == 0 ? 0.0 : -std::numeric_limits<double>::infinity();
		return -0.5 * (d / sigma) * (d / sigma) - std::log(sigma * std::sqrt(2 * M_PI));
	};
	return logGaussian(leg.x - fit.x, ctx.sp.leg_position_noise) + logGaussian(leg.y - fit.y, ctx.sp.leg_position_noise) +
		   logGaussian(core::angleDiff(leg.theta, fit.theta, 2 * M_PI), ctx.sp.leg_angle_noise);
}

double LegRefit::logReverseOfRefit(const model::Leg& before, const model::Leg& after)
{
	const bool same = before.x == after.x && before.y == after.y && before.theta == after.theta &&
					  before.texture == after.texture;
	return same ? 0 : -std::numeric_limits<double>::infinity();
}
}  // namespace whiskermap::inference::moves
