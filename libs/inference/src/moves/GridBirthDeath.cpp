#include <whiskermap/inference/moves/GridBirthDeath.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

namespace
{
double logCount(size_t n) { return std::log(static_cast<double>(n)); }
}  // namespace

std::optional<Proposal> GridBirthDeath::legBirth(MoveContext& ctx)
{
	model::Blackboard& bb = ctx.bb;
	const size_t n = bb.shapelets().size(), s = ctx.rng.pick(n);
	const size_t k = ctx.rng.pick(m_grid.legs.size());
	if (bb.shapeletParent(s) != NONE) return std::nullopt;
	model::Leg l = m_grid.legs[k];
	l.parent = NONE;
	m_birth = true, m_table = false;
	m_id = bb.addLeg(l);
	bb.setShapeletParent(s, m_id);
	Proposal p{Move::Priming, model::logOddsLeg(bb, m_id)};  // eq. 20
	p.logForward = -logCount(n) - logCount(m_grid.legs.size());
	p.logReverse = -logCount(bb.legCount());
	return p;
}

std::optional<Proposal> GridBirthDeath::legDeath(MoveContext& ctx)
{
	const model::Blackboard& bb = ctx.bb;
	const size_t legs = bb.legCount();
	if (legs == 0) return std::nullopt;
	const Id l = nthLeg(bb, ctx.rng.pick(legs));
	if (bb.leg(l).parent != NONE || bb.shapeletsOf(l).size() != 1 || !bb.evidence(l).empty() ||
		m_grid.legIndex(bb.leg(l)) < 0)
		return std::nullopt;
	m_birth = false, m_table = false, m_id = l;
	Proposal p{Move::Death, -model::logOddsLeg(bb, l)};  // eq. 20
	p.logForward = -logCount(legs);
	p.logReverse = -logCount(bb.shapelets().size()) - logCount(m_grid.legs.size());
	return p;
}

std::optional<Proposal> GridBirthDeath::tableBirth(MoveContext& ctx)
{
	model::Blackboard& bb = ctx.bb;
	const size_t k = ctx.rng.pick(m_grid.tables.size());
	if (bb.tableCount() >= m_grid.maxTables) return std::nullopt;
	m_birth = true, m_table = true;
	m_id = bb.addTable(m_grid.tables[k]);
	for (Id l = 0; l < bb.legIdBound(); l++)  // adopts every free leg within the gate of a corner
		if (bb.hasLeg(l) && bb.leg(l).parent == NONE && LegReparent::withinGate(ctx, l, m_id)) bb.setLegParent(l, m_id);
	Proposal p{Move::Parent, model::logOddsTable(bb, m_id)};  // eq. 20
	p.logForward = -logCount(m_grid.tables.size());
	p.logReverse = -logCount(bb.tableCount());
	return p;
}

std::optional<Proposal> GridBirthDeath::tableDeath(MoveContext& ctx)
{
	model::Blackboard& bb = ctx.bb;
	const size_t tables = bb.tableCount();
	if (tables == 0) return std::nullopt;
	const Id t = nthTable(bb, ctx.rng.pick(tables));
	if (m_grid.tableIndex(bb.table(t)) < 0) return std::nullopt;
	for (Id l = 0; l < bb.legIdBound(); l++)  // the birth at t's pose would adopt exactly t's legs
		if (bb.hasLeg(l) && bb.leg(l).parent == NONE && LegReparent::withinGate(ctx, l, t)) return std::nullopt;
	m_birth = false, m_table = true, m_id = t;
	Proposal p{Move::Death, -model::logOddsTable(bb, t)};  // eq. 20
	p.logForward = -logCount(tables);
	p.logReverse = -logCount(m_grid.tables.size());
	return p;
}

void GridBirthDeath::finish(MoveContext& ctx, bool accepted)
{
	if (accepted == m_birth) return;  // an accepted birth, a rejected death
	if (m_table)
		ctx.bb.removeTable(m_id);  // its legs lose their parent
	else
		ctx.bb.removeLeg(m_id);
}
}  // namespace whiskermap::inference::moves
