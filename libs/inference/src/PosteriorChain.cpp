#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/PosteriorChain.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/LibraryScan.h>
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/model/Densities.h>

#include <array>
#include <cmath>

namespace whiskermap::inference
{
namespace
{
SamplerParams chainParams(SamplerParams p)
{
	p.acceptance = AcceptanceRule::ReversibleJump;
	p.proposals = Proposals::DataDriven;
	return p;
}
}  // namespace

PosteriorChain::PosteriorChain(const model::ModelParams& model, SamplerParams params)
	: m_model(model), m_params(chainParams(params)), m_scan(moves::libraryScan(m_model)), m_bb(m_model)
{
}

std::vector<PosteriorChain::Summary> PosteriorChain::run(
	const model::Blackboard& start, uint64_t seed, long burnIn, long samples, long thin)
{
	// The start: every hypothesis awake (a lasting map's region marks its context dormant;
	// the chain moves it too), and each leg that explains nothing exactly at its table's
	// corner, as a corner birth puts it (a table refit since may have left it a few um off:
	// without this, no move could undo it, since each reverse needs it exactly there).
	m_bb = start;
	for (model::Id t = 0; t < m_bb.tableIdBound(); t++)
		if (m_bb.hasTable(t)) m_bb.setTableDormant(t, false);
	for (model::Id l = 0; l < m_bb.legIdBound(); l++)
	{
		if (!m_bb.hasLeg(l)) continue;
		m_bb.setLegDormant(l, false);
		const model::Leg& leg = m_bb.leg(l);
		if (leg.parent != model::NONE && !m_bb.explains(l))
			m_bb.setLeg(l, moves::LegBirthDeath::atCorner(m_model, m_bb.table(leg.parent), leg.corner, leg.parent));
	}
	m_rng.seed(seed);
	StepResult counts;
	moves::MoveContext ctx(m_bb, m_model, m_params, m_rng, m_acceptance);
	ctx.result = &counts;
	ctx.beta = 1;
	std::vector<Summary> out(static_cast<size_t>(start.tableIdBound()));
	std::vector<std::array<double, 7>> sums(out.size(), std::array<double, 7>{});  // n, x, y, yaw, x^2, y^2, yaw^2
	for (long i = 0; i < burnIn; i++) m_scan.step(ctx);
	for (long k = 0; k < samples; k++)
	{
		for (long j = 0; j < thin; j++) m_scan.step(ctx);
		for (model::Id t = 0; t < start.tableIdBound(); t++)
		{
			if (!start.hasTable(t)) continue;
			const model::Table& T = start.table(t);
			double best = T.leg_width;  // the nearest table of T's class within its leg width
			model::Id holder = model::NONE;
			m_bb.forEachTableNear(T.x, T.y, T.leg_width, [&](model::Id u) {
				const model::Table& U = m_bb.table(u);
				const double d = std::hypot(U.x - T.x, U.y - T.y);
				if (U.cls == T.cls && d <= best) best = d, holder = u;
			});
			if (holder == model::NONE) continue;
			const model::Table& U = m_bb.table(holder);
			const double d[3] = {U.x - T.x, U.y - T.y, core::angleDiff(U.theta, T.theta, M_PI)};
			std::array<double, 7>& s = sums[static_cast<size_t>(t)];
			s[0] += 1;
			for (int a = 0; a < 3; a++) s[1 + a] += d[a], s[4 + a] += d[a] * d[a];
		}
	}
	for (size_t t = 0; t < out.size(); t++)
	{
		const std::array<double, 7>& s = sums[t];
		if (s[0] == 0) continue;
		const auto sd = [&](int a) { return std::sqrt(std::max(0.0, s[4 + a] / s[0] - (s[1 + a] / s[0]) * (s[1 + a] / s[0]))); };
		out[t] = {s[0] / static_cast<double>(samples), sd(0), sd(1), sd(2)};
	}
	return out;
}
}  // namespace whiskermap::inference
