#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/SplitMerge.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;

namespace
{
constexpr double NO_REVERSE = -std::numeric_limits<double>::infinity();
}

// The reverse of a link; exact local change of logJoint.
Proposal SplitMerge::split(MoveContext& ctx, size_t s)
{
	model::Blackboard& bb = ctx.bb;
	const bool stochastic = ctx.stochasticRefits();
	m_split = true;
	m_shapelet = s;
	m_leg = bb.shapeletParent(s);
	m_oldLeg = bb.leg(m_leg);
	const bool atFit = !stochastic && ctx.atFit(m_leg);
	Proposal p{Move::Child, -model::logShapeletLinkGain(bb, s, m_leg)};
	bb.setShapeletParent(s, model::NONE);
	const bool drew = stochastic ? ctx.drawRefit(m_leg, p.logTarget, p.logForward) : ctx.refitInPlace(m_leg, p.logTarget);
	m_other = bb.addLeg(ctx.newLegFor(s));
	bb.setShapeletParent(s, m_other);
	p.logTarget += model::logOddsLeg(bb, m_other);
	p.logForward += LegBirthDeath::logBirthMass(ctx, s, bb.leg(m_other));
	if (!stochastic)
		p.logReverse = atFit ? 0 : NO_REVERSE;
	else if (!drew)
		p.logReverse = NO_REVERSE;
	else  // the merge's refit of the old leg with s back on it
	{
		bb.setShapeletParent(s, m_leg);
		p.logReverse = ctx.logRefitTo(m_leg, m_oldLeg);
		bb.setShapeletParent(s, m_other);
	}
	return p;
}

// Other is removed (its local log-odds, eq. 20, with its contacts unlinked), the contacts
// link to l one by one, and l refits to all its contacts.
std::optional<Proposal> SplitMerge::merge(MoveContext& ctx, Id l, Id other)
{
	model::Blackboard& bb = ctx.bb;
	m_moved.assign(bb.shapeletsOf(other).begin(), bb.shapeletsOf(other).end());
	if (!bb.explains(other)) return std::nullopt;
	m_split = false;
	m_leg = l, m_other = other;
	m_oldLeg = bb.leg(l), m_oldOther = bb.leg(other);
	m_oldEvidence = bb.evidence(l), m_otherEvidence = bb.evidence(other);
	const bool stochastic = ctx.stochasticRefits();
	Proposal p{Move::Child};
	p.logReverse = NO_REVERSE;
	// The split of other's one contact: a birth's leg for it, l refitted without it.
	const auto lone = m_moved.size() == 1 ? static_cast<size_t>(m_moved[0]) : size_t{0};
	const bool splittable = m_moved.size() == 1 && m_otherEvidence.empty() && m_oldOther.parent == model::NONE &&
							m_oldOther.texture == bb.shapelets()[lone].texture && m_oldOther.wx == ctx.mp.leg_width &&
							m_oldOther.wy == m_oldOther.wx;
	if (splittable && (stochastic || ctx.atFit(l))) p.logReverse = LegBirthDeath::logBirthMass(ctx, lone, m_oldOther);
	double gain = -model::logOddsLeg(bb, other);
	bb.removeLeg(other);
	for (const Id s : m_moved)
	{
		gain += model::logShapeletLinkGain(bb, static_cast<size_t>(s), l);
		bb.setShapeletParent(static_cast<size_t>(s), l);
	}
	if (!m_otherEvidence.empty())
	{
		// The folded contacts move too: log-odds of l before and after (eq. 20) differ by them.
		gain -= model::logOddsLeg(bb, l);
		model::LegEvidence merged = m_oldEvidence;
		merged.merge(m_otherEvidence);
		bb.setEvidence(l, merged);
		gain += model::logOddsLeg(bb, l);
	}
	if (!(stochastic ? ctx.drawRefit(l, gain, p.logForward) : ctx.refitInPlace(l, gain)))
	{
		undoMerge(ctx);
		return std::nullopt;
	}
	if (stochastic && splittable)  // the split's refit of l without s
	{
		bb.setShapeletParent(lone, model::NONE);
		p.logReverse += ctx.logRefitTo(l, m_oldLeg);
		bb.setShapeletParent(lone, l);
	}
	p.logTarget = gain;
	return p;
}

void SplitMerge::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	if (!m_split) return undoMerge(ctx);
	ctx.bb.removeLeg(m_other);
	ctx.bb.setLeg(m_leg, m_oldLeg);
	ctx.bb.setShapeletParent(m_shapelet, m_leg);
}

void SplitMerge::undoMerge(MoveContext& ctx)
{
	ctx.bb.setLeg(m_leg, m_oldLeg);
	ctx.bb.setEvidence(m_leg, m_oldEvidence);
	const Id back = ctx.bb.addLeg(m_oldOther, m_otherEvidence);
	for (const Id s : m_moved) ctx.bb.setShapeletParent(static_cast<size_t>(s), back);
}

void SplitMerge::candidates(const MoveContext& ctx, Id l, std::vector<Id>& out)
{
	out.clear();
	const model::Leg& leg = ctx.bb.leg(l);
	// Two contacts one leg explains are within its diagonal plus two gates of each other, so
	// the leg centres are within that plus one half-diagonal each.
	const double w = ctx.mp.leg_width, reach = 2 * w * std::sqrt(2.0) + 2 * ctx.mp.parent_gate;
	ctx.bb.forEachLegNear(leg.x, leg.y, reach, [&](Id o) {
		if (o != l && ctx.bb.explains(o)) out.push_back(o);
	});
}
}  // namespace whiskermap::inference::moves
