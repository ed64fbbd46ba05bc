#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/TableRefit.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;

std::optional<Proposal> TableRefit::propose(MoveContext& ctx, Id t)
{
	model::Blackboard& bb = ctx.bb;
	m_table = t;
	m_savedLegs.clear();
	for (const Id l : bb.legsOf(t)) m_savedLegs.emplace_back(l, bb.leg(l));
	m_old = bb.table(t);
	const double before = model::logJointAround(bb, t);
	bool valid = true;
	for (int round = 0; round < 2 && valid; round++)
	{
		m_fitLegs.clear();
		m_fitCorners.clear();
		for (const auto& [l, saved] : m_savedLegs)
			if (bb.explains(l)) m_fitLegs.push_back(&bb.leg(l)), m_fitCorners.push_back(bb.leg(l).corner);
		if (m_fitLegs.empty()) return std::nullopt;  // nothing to fit (and nothing changed yet)
		// The plain refit fits the pose from the old table both rounds; the resize from its
		// own last fit, whose size it changed.
		const model::Table& start = m_resize && round > 0 ? bb.table(t) : m_old;
		if (ctx.broad())  // one random-walk step of the table; its legs stay (broad proposals)
		{
			model::Table stepped = m_old;
			ctx.randomWalk(stepped.x, stepped.y, stepped.theta);
			bb.setTable(t, stepped);
			break;
		}
		model::Table fitted = fitTable(ctx.mp, start, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
		if (m_resize) fitted = fitTableSize(ctx.mp, fitted, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
		bb.setTable(t, fitted);
		for (const auto& [l, saved] : m_savedLegs)
		{
			model::Leg fit;
			if (!bb.explains(l)) continue;
			valid = valid && ctx.fittedLeg(l, &bb.table(t), fit);
			if (valid) bb.setLeg(l, fit);
		}
	}
	const model::Table& now = bb.table(t);
	const bool same = now.x == m_old.x && now.y == m_old.y && now.theta == m_old.theta &&
					  now.d_length == m_old.d_length && now.d_width == m_old.d_width;
	double logReverse = same || ctx.broad() ? 0 : -std::numeric_limits<double>::infinity();
	for (const auto& [l, saved] : m_savedLegs)
	{
		if (!bb.explains(l))
		{
			model::Leg moved = saved;
			model::tableCorner(now, saved.corner, ctx.mp, moved.x, moved.y);
			moved.theta = now.theta;
			bb.setLeg(l, moved);
		}
		logReverse += LegRefit::logReverseOfRefit(saved, bb.leg(l));
	}
	if (!valid)
	{
		finish(ctx, false);
		return std::nullopt;
	}
	Proposal p{Move::Refit, model::logJointAround(bb, t) - before};
	p.logReverse = logReverse;
	return p;
}

void TableRefit::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	ctx.bb.setTable(m_table, m_old);
	for (const auto& [l, saved] : m_savedLegs) ctx.bb.setLeg(l, saved);
}
}  // namespace whiskermap::inference::moves
