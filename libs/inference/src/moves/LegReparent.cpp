#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

std::optional<Proposal> LegReparent::propose(MoveContext& ctx, Id l)
{
	const model::Blackboard& bb = ctx.bb;
	const model::Leg& leg = bb.leg(l);
	m_candidates.clear();
	if (leg.parent != NONE) m_candidates.push_back(NONE);
	const double reach = ctx.mp.maxDiagonal() / 2 + ctx.mp.parent_gate;
	bb.forEachTableNear(leg.x, leg.y, reach, [&](Id t) {
		if (t != leg.parent && withinGate(ctx, l, t)) m_candidates.push_back(t);
	});
	if (m_candidates.empty()) return std::nullopt;
	m_leg = l;
	m_to = m_candidates[ctx.rng.pick(m_candidates.size())];
	Proposal p{Move::Reparent, model::logLegLinkGain(bb, l, m_to) - model::logLegLinkGain(bb, l, leg.parent)};
	const auto n = static_cast<double>(m_candidates.size());
	p.logForward = -std::log(n);
	// From the new parent: none (if the new parent is a table), and the same tables, with the
	// old parent in place of the new one when it is within the gate.
	const bool back = leg.parent == NONE || withinGate(ctx, l, leg.parent);
	const double reverse = n - (leg.parent != NONE) + (leg.parent != NONE && back);
	p.logReverse = back ? -std::log(reverse) : -std::numeric_limits<double>::infinity();
	return p;
}

void LegReparent::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) ctx.bb.setLegParent(m_leg, m_to);
}

bool LegReparent::withinGate(const MoveContext& ctx, Id l, Id t)
{
	const model::Leg& leg = ctx.bb.leg(l);
	const model::Table& table = ctx.bb.table(t);
	double cx = 0, cy = 0;
	model::tableCorner(table, model::logLegGivenTable(leg, table, ctx.mp).corner, ctx.mp, cx, cy);
	return std::hypot(cx - leg.x, cy - leg.y) <= ctx.mp.parent_gate;
}
}  // namespace whiskermap::inference::moves
