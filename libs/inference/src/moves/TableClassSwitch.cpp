#include <whiskermap/inference/moves/TableClassSwitch.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
std::optional<Proposal> TableClassSwitch::propose(MoveContext& ctx, model::Id t)
{
	const int k = ctx.mp.classCount();
	if (k < 2) return std::nullopt;
	const int from = ctx.bb.table(t).cls;
	int to = static_cast<int>(ctx.rng.pick(static_cast<size_t>(k - 1)));
	if (to >= from) to++;  // uniform over the other classes
	return switchTo(ctx, t, to);
}

Proposal TableClassSwitch::switchTo(MoveContext& ctx, model::Id t, int to)
{
	m_table = t;
	m_old = ctx.bb.table(t);
	const double before = model::logJointAround(ctx.bb, t);
	model::Table now = m_old;
	now.cls = to;
	now.d_length = now.d_width = 0;  // snapped to the new class's size
	now.leg_width = ctx.mp.legWidthOf(to);
	now.texture = ctx.mp.textureOf(to);
	ctx.bb.setTable(t, now);
	Proposal p{Move::Refit, model::logJointAround(ctx.bb, t) - before};
	p.logForward = p.logReverse = -std::log(static_cast<double>(ctx.mp.classCount() - 1));
	// A resized table (size_moves), or one with legs of its own (eq. 26), is snapped to the
	// nominal size and legs: switching back does not restore its own, so that switch has no reverse.
	if (m_old.d_length != 0 || m_old.d_width != 0 || m_old.leg_width != ctx.mp.legWidthOf(m_old.cls) ||
		m_old.texture != ctx.mp.textureOf(m_old.cls))
		p.logReverse = -std::numeric_limits<double>::infinity();
	return p;
}

void TableClassSwitch::finish(MoveContext& ctx, bool accepted)
{
	if (!accepted) ctx.bb.setTable(m_table, m_old);
}
}  // namespace whiskermap::inference::moves
