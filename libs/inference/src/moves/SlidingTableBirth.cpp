#include <whiskermap/inference/TableProposals.h>
#include <whiskermap/inference/moves/SlidingTableBirth.h>
#include <whiskermap/model/Densities.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
Proposal SlidingTableBirth::propose(MoveContext& ctx, model::Id l, const model::Table& chosen)
{
	Proposal p = m_birth.birthOf(ctx, l, chosen);
	const model::Id t = ctx.bb.leg(l).parent;  // the new table
	const std::optional<Proposal> refit = m_refit.propose(ctx, t);
	m_refitted = refit.has_value();
	if (refit) p.logTarget += refit->logTarget;  // logJointAround(t) after the refit minus after the birth
	p.logReverse = -std::numeric_limits<double>::infinity();
	return p;
}

void SlidingTableBirth::finish(MoveContext& ctx, bool accepted)
{
	if (m_refitted) m_refit.finish(ctx, accepted);  // the legs back first: the birth's undo relinks them
	m_birth.finish(ctx, accepted);
}

void SlidingTableBirth::candidates(const MoveContext& ctx, model::Id l, std::vector<model::Table>& out)
{
	out.clear();
	// When the corner binds a leg tighter than its contacts do, the parent move refits every
	// leg it adopts already (TableBirthDeath::birth).
	if (ctx.bb.leg(l).parent != model::NONE || ctx.mp.cornersTighterThanReadings()) return;
	for (int k = 0; k < ctx.mp.classCount(); k++)
		if (std::abs(ctx.bb.leg(l).texture - ctx.mp.textureOf(k)) <= MAX_TEXTURE_SIGMAS * ctx.mp.sigma_tau)
			tablesForPairs(ctx.bb, l, k, out);
	// A pair table is fitted between its two legs: each stands half the mismatch of their
	// distance off its corner.
	const double reach = MAX_SLIDE_WIDTHS * ctx.mp.leg_width;
	const model::Leg& leg = ctx.bb.leg(l);
	out.erase(std::remove_if(out.begin(), out.end(), [&](const model::Table& t) {
		double cx[4], cy[4], d2 = 0;
		model::tableCorners(t, ctx.mp, cx, cy);
		model::nearestCorner(cx, cy, leg.x, leg.y, d2);
		return d2 > reach * reach;
	}), out.end());
}
}  // namespace whiskermap::inference::moves
