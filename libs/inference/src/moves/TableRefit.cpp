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
	if (ctx.stochasticRefits()) return drawn(ctx, t, before);
	bool valid = true;
	for (int round = 0; round < 2 && valid; round++)
	{
		// The plain refit fits the pose from the old table both rounds; the resize from its
		// own last fit, whose size it changed.
		model::Table fitted;
		if (!fitToLegs(ctx, m_resize && round > 0 ? bb.table(t) : m_old, fitted))
			return std::nullopt;  // nothing to fit (and nothing changed yet)
		if (ctx.broad())  // one random-walk step of the table; its legs stay (broad proposals)
		{
			model::Table stepped = m_old;
			ctx.randomWalk(stepped.x, stepped.y, stepped.theta);
			bb.setTable(t, stepped);
			break;
		}
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

bool TableRefit::fitToLegs(const MoveContext& ctx, const model::Table& start, model::Table& out)
{
	const model::Blackboard& bb = ctx.bb;
	m_fitLegs.clear();
	m_fitCorners.clear();
	for (const auto& [l, saved] : m_savedLegs)
		if (bb.explains(l)) m_fitLegs.push_back(&bb.leg(l)), m_fitCorners.push_back(bb.leg(l).corner);
	if (m_fitLegs.empty()) return false;
	out = fitTable(ctx.mp, start, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
	if (m_resize) out = fitTableSize(ctx.mp, out, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
	return true;
}

// The table drawn about its fit from the board as it is (and the reverse: the old table's
// density about the fit from the new board); its legs that explain data stay where they are,
// its invented legs go to the new corners, which the reverse undoes only if they stood at
// the old ones.
std::optional<Proposal> TableRefit::drawn(MoveContext& ctx, Id t, double before)
{
	model::Blackboard& bb = ctx.bb;
	model::Table fit, back;
	if (!fitToLegs(ctx, m_old, fit)) return std::nullopt;
	const model::Table d = ctx.drawnTable(fit, m_resize);
	Proposal p{Move::Refit};
	p.logForward = ctx.logTableDrawnAbout(d, fit, m_resize);
	bb.setTable(t, d);
	for (const auto& [l, saved] : m_savedLegs)
	{
		if (bb.explains(l)) continue;
		model::Leg moved = saved;
		model::tableCorner(m_old, saved.corner, ctx.mp, moved.x, moved.y);
		if (moved.x != saved.x || moved.y != saved.y || m_old.theta != saved.theta)
			p.logReverse = -std::numeric_limits<double>::infinity();
		model::tableCorner(d, saved.corner, ctx.mp, moved.x, moved.y);
		moved.theta = d.theta;
		bb.setLeg(l, moved);
	}
	fitToLegs(ctx, d, back);  // the same legs: a fit exists
	p.logReverse += ctx.logTableDrawnAbout(m_old, back, m_resize);
	p.logTarget = model::logJointAround(bb, t) - before;
	return p;
}

void TableRefit::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	ctx.bb.setTable(m_table, m_old);
	for (const auto& [l, saved] : m_savedLegs) ctx.bb.setLeg(l, saved);
}
}  // namespace whiskermap::inference::moves
