#include <whiskermap/inference/moves/GridShift.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

namespace
{
/** Another index than `from` (>= 0) below n, uniformly; -log(n - 1) is its probability. */
size_t other(SamplerRandom& rng, size_t n, int from)
{
	const size_t to = rng.pick(n - 1);
	return to + (to >= static_cast<size_t>(from));
}

double logChoices(size_t hypotheses, size_t poses)
{
	return -std::log(static_cast<double>(hypotheses)) - std::log(static_cast<double>(poses - 1));
}
}  // namespace

std::optional<Proposal> GridShift::table(MoveContext& ctx)
{
	model::Blackboard& bb = ctx.bb;
	const size_t tables = bb.tableCount(), poses = m_grid.tables.size();
	if (tables == 0 || poses < 2) return std::nullopt;
	const Id t = nthTable(bb, ctx.rng.pick(tables));
	const int from = m_grid.tableIndex(bb.table(t));
	if (from < 0) return std::nullopt;
	m_isTable = true, m_id = t, m_oldTable = bb.table(t);
	const double before = model::logJointAround(bb, t);
	bb.setTable(t, m_grid.tables[other(ctx.rng, poses, from)]);
	for (const Id l : bb.legsOf(t))
		if (!LegReparent::withinGate(ctx, l, t))
		{
			bb.setTable(t, m_oldTable);
			return std::nullopt;
		}
	Proposal p{Move::Refit, model::logJointAround(bb, t) - before};
	p.logForward = p.logReverse = logChoices(tables, poses);
	return p;
}

std::optional<Proposal> GridShift::leg(MoveContext& ctx)
{
	model::Blackboard& bb = ctx.bb;
	const size_t legs = bb.legCount(), poses = m_grid.legs.size();
	if (legs == 0 || poses < 2) return std::nullopt;
	const Id l = nthLeg(bb, ctx.rng.pick(legs));
	const int from = m_grid.legIndex(bb.leg(l));
	if (from < 0) return std::nullopt;
	m_isTable = false, m_id = l, m_oldLeg = bb.leg(l);
	const double before = model::logOddsLeg(bb, l);  // eq. 20: the board without l is the same after
	model::Leg moved = m_grid.legs[other(ctx.rng, poses, from)];
	moved.parent = m_oldLeg.parent;
	bb.setLeg(l, moved);
	if (moved.parent != NONE && !LegReparent::withinGate(ctx, l, moved.parent))
	{
		bb.setLeg(l, m_oldLeg);
		return std::nullopt;
	}
	Proposal p{Move::Refit, model::logOddsLeg(bb, l) - before};
	p.logForward = p.logReverse = logChoices(legs, poses);
	return p;
}

void GridShift::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	if (m_isTable)
		ctx.bb.setTable(m_id, m_oldTable);
	else
		ctx.bb.setLeg(m_id, m_oldLeg);
}
}  // namespace whiskermap::inference::moves
