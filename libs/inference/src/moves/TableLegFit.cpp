#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/TableLegFit.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
constexpr double MAX_STEP = 0.005;  ///< the leg width fit's step at most, metres

bool TableLegFit::apply(MoveContext& ctx, double legWidth, double texture)
{
	model::Blackboard& bb = ctx.bb;
	model::Table t = bb.table(m_table);
	t.leg_width = legWidth, t.texture = texture;
	bb.setTable(m_table, t);
	for (const auto& [l, saved] : m_savedLegs)
	{
		model::Leg fit = bb.leg(l);
		if (bb.explains(l))
		{
			if (!ctx.fittedLeg(l, &bb.table(m_table), fit)) return false;
		}
		else  // an invented leg: a square of the table's legs where it stands (as a birth makes it)
			fit.wx = fit.wy = legWidth, fit.texture = texture;
		bb.setLeg(l, fit);
	}
	return true;
}

std::optional<Proposal> TableLegFit::propose(MoveContext& ctx, Id t)
{
	model::Blackboard& bb = ctx.bb;
	if (ctx.broad()) return std::nullopt;
	const model::ObjectClass& cls = ctx.mp.classes.at(static_cast<size_t>(bb.table(t).cls));
	if (!cls.legsVary()) return std::nullopt;
	m_table = t;
	m_old = bb.table(t);
	m_savedLegs.clear();
	bool any = false;
	for (const Id l : bb.legsOf(t)) m_savedLegs.emplace_back(l, bb.leg(l)), any = any || bb.explains(l);
	if (!any) return std::nullopt;
	const double before = model::logJointAround(bb, t);
	double width = m_old.leg_width, texture = m_old.texture;
	bool valid = true;
	// Texture (eqs. 6 + 26): (sum tau_L / sigma_tau^2 + tau_k / (2 s^2)) / (n / sigma_tau^2 + 1 / (2 s^2))
	// over the legs that explain data; their textures then refitted to the new one; twice.
	const double kPrior = 1 / (2 * cls.texture_sigma * cls.texture_sigma), kLeg = 1 / (ctx.mp.sigma_tau * ctx.mp.sigma_tau);
	if (cls.texture_sigma > 0)
		for (int round = 0; round < 2 && valid; round++)
		{
			double num = kPrior * cls.texture, den = kPrior;
			for (const auto& [l, saved] : m_savedLegs)
				if (bb.explains(l)) num += kLeg * bb.leg(l).texture, den += kLeg;
			texture = std::clamp(num / den, 0.0, 1.0);
			valid = apply(ctx, width, texture);
		}
	double after = valid ? model::logJointAround(bb, t) : 0;
	// Leg width: the vertex of the parabola through the exact target at width - h, width, width + h.
	if (valid && cls.leg_width_sigma > 0)
	{
		// Within two steps, at least 1 mm and at most half the smaller leg spacing (wider legs
		// would touch each other).
		const model::Table& now = bb.table(t);
		const double h = std::min(cls.leg_width_sigma / 2, MAX_STEP), w0 = width, lo = std::max(1e-3, w0 - 2 * h);
		const double hi = std::min(w0 + 2 * h, std::min(ctx.mp.lengthOf(now), ctx.mp.widthOf(now)) / 2);
		const double f0 = after;
		double fm = -std::numeric_limits<double>::infinity(), fp = fm, held = w0;  // held: the width the board holds
		if (w0 - h >= lo && apply(ctx, held = w0 - h, texture)) fm = model::logJointAround(bb, t);
		if (w0 + h <= hi && apply(ctx, held = w0 + h, texture)) fp = model::logJointAround(bb, t);
		const double curvature = fm - 2 * f0 + fp;
		double best = fm > f0 ? w0 - h : w0, fBest = std::max(f0, fm);
		if (fp > fBest) best = w0 + h, fBest = fp;
		if (std::isfinite(curvature) && curvature < 0)
		{
			const double vertex = std::clamp(w0 + h * (fm - fp) / (2 * curvature), lo, std::max(lo, hi));
			if (apply(ctx, held = vertex, texture))
			{
				const double fv = model::logJointAround(bb, t);
				if (fv > fBest) best = vertex, fBest = fv;
			}
		}
		width = best;
		if (held != best)  // else the board holds it, scored
		{
			valid = apply(ctx, best, texture);
			after = valid ? model::logJointAround(bb, t) : 0;
		}
		else
			after = fBest;
	}
	if (!valid)
	{
		finish(ctx, false);
		return std::nullopt;
	}
	Proposal p{Move::Refit, after - before};
	const bool same = width == m_old.leg_width && texture == m_old.texture;
	p.logReverse = same ? 0 : -std::numeric_limits<double>::infinity();
	// (a leg's width is its table's: unchanged when the table's is)
	for (const auto& [l, saved] : m_savedLegs) p.logReverse += LegRefit::logReverseOfRefit(saved, bb.leg(l));
	return p;
}

void TableLegFit::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	ctx.bb.setTable(m_table, m_old);
	for (const auto& [l, saved] : m_savedLegs) ctx.bb.setLeg(l, saved);
}
}  // namespace whiskermap::inference::moves
