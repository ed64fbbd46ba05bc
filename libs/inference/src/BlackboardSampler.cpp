#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference
{
using model::Id;
using model::Leg;
using model::NONE;

BlackboardSampler::BlackboardSampler(const model::ModelParams& model, const SamplerParams& params)
	: m_model(model),
	  m_params(params),
	  m_bb(model),
	  m_acceptance(params.acceptance),
	  m_ctx(m_bb, m_model, m_params, m_rng, m_acceptance),
	  m_moves(m_model),
	  m_best(model)
{
	for (size_t k = 0; k < m_moves.entries().size(); k++)
		if (m_moves.entries()[k].target == moves::Target::Shapelet) m_shapeletMoves.push_back(k);
}

StepResult BlackboardSampler::step(
	const std::vector<obs::Shapelet>& shapelets, uint64_t seed, int snapshotTemperature)
{
	return step(shapelets, {}, seed, snapshotTemperature);
}

StepResult BlackboardSampler::step(
	const std::vector<obs::Shapelet>& shapelets, const std::vector<obs::SweptSector>& swept, uint64_t seed,
	int snapshotTemperature)
{
	m_bb.reset(shapelets, swept);
	m_scoredAfter = NOT_SCORED;
	m_ctx.annealing = false;
	StepResult result;
	run(result, seed, snapshotTemperature);
	return result;
}

StepResult BlackboardSampler::anneal(const model::Blackboard& start, uint64_t seed, int snapshotTemperature)
{
	m_bb = start;
	m_scoredAfter = NOT_SCORED;
	m_ctx.annealing = true;
	StepResult result;
	m_ctx.result = &result;
	m_rng.seed(seed);
	associate();
	m_ctx.changed();
	checkpoint(result);  // the map as it was, with the new contacts associated: the first candidate
	result.initialLogPosterior = result.logPosterior;
	run(result, seed ^ 0x5DEECE66Dull, snapshotTemperature);
	return result;
}

void BlackboardSampler::run(StepResult& result, uint64_t seed, int snapshotTemperature)
{
	m_ctx.result = &result;
	result.moveTypes.clear();
	result.moveTypes.reserve(m_moves.entries().size());
	for (const moves::MoveEntry& e : m_moves.entries()) result.moveTypes.push_back({e.name, 0, 0});
	m_rng.seed(seed);
	const auto& betas = m_params.schedule.betas();
	for (size_t k = 0; k < betas.size(); k++)
	{
		const bool coldest = k + 1 == betas.size();
		const int sweeps = coldest ? m_params.coldest_sweeps : m_params.sweeps_per_temperature;
		for (int i = 0; i < sweeps; i++)
		{
			sweep(betas[k]);
			if (coldest) checkpoint(result);
		}
		if (static_cast<int>(k) == snapshotTemperature) result.snapshot = m_bb.compact();
	}
	// Zero temperature, from the best board: only improvements (doc/sampler.md, "Polish").
	m_bb = m_best;
	for (int i = 0; i < m_params.polish_sweeps; i++)
	{
		m_ctx.searchPoses = i + 1 == m_params.polish_sweeps;  // the pose search: last sweep only
		sweep(std::numeric_limits<double>::infinity());
		checkpoint(result);
	}
	m_ctx.searchPoses = false;
	result.map = m_best.compact();
	m_ctx.result = nullptr;
	m_ctx.entry = moves::MoveContext::NO_ENTRY;
}

// Data association first: each shapelet without a leg takes the best of linking to a nearby
// leg (which refits) or a new leg of its own, when that beats leaving it unexplained.
void BlackboardSampler::associate()
{
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
	{
		if (m_bb.explained(s)) continue;
		m_ctx.legsNearShapelet(s, m_candidates);
		Id bestLeg = NONE;
		double bestGain = 0;
		for (const Id l : m_candidates)
		{
			const Leg old = m_bb.leg(l);
			double gain = model::logShapeletLinkGain(m_bb, s, l);
			m_bb.setShapeletParent(s, l);
			m_ctx.refitInPlace(l, gain);
			m_bb.setShapeletParent(s, NONE);
			m_bb.setLeg(l, old);
			if (gain > bestGain) bestGain = gain, bestLeg = l;
		}
		const Id bestWall = bestWallFor(s, bestGain);
		const Id id = m_bb.addLeg(m_ctx.newLegFor(s));
		m_bb.setShapeletParent(s, id);
		if (model::logOddsLeg(m_bb, id) > bestGain) continue;  // the new leg stays
		m_bb.removeLeg(id);
		if (bestWall != NONE)
		{
			m_bb.setShapeletWall(s, bestWall);
			continue;
		}
		if (bestLeg == NONE) continue;
		m_bb.setShapeletParent(s, bestLeg);
		double ignored = 0;
		m_ctx.refitInPlace(bestLeg, ignored);
	}
}

void BlackboardSampler::checkpoint(StepResult& result)
{
	uint64_t accepted = 0;
	for (const uint32_t a : result.accepted) accepted += a;
	if (accepted == m_scoredAfter) return;  // the board scored last time, unchanged
	m_scoredAfter = accepted;
	const double lp = model::logJoint(m_bb);
	if (lp <= result.logPosterior) return;
	result.logPosterior = lp;
	m_best = m_bb;
}

// Shapelets without a leg first (priming), then the tables and the legs on the board at
// sweep start, not dormant, in ascending ids; then the prune.
void BlackboardSampler::sweep(double beta)
{
	m_ctx.beta = beta;
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
		for (const size_t k : m_shapeletMoves)
			if (!m_bb.explained(s))
			{
				m_ctx.entry = k;
				m_moves.entries()[k].visit(m_ctx, static_cast<Id>(s));
			}

	m_tableOrder.clear();
	m_legOrder.clear();
	for (Id t = 0; t < m_bb.tableIdBound(); t++)
		if (m_bb.hasTable(t) && !m_bb.tableDormant(t)) m_tableOrder.push_back(t);
	for (Id l = 0; l < m_bb.legIdBound(); l++)
		if (m_bb.hasLeg(l) && !m_bb.legDormant(l)) m_legOrder.push_back(l);
	for (const Id t : m_tableOrder)
		if (m_bb.hasTable(t)) visit(moves::Target::Table, t);
	for (const Id l : m_legOrder)
		if (m_bb.hasLeg(l)) visit(moves::Target::Leg, l);
	m_wallOrder.clear();
	for (Id w = 0; w < m_bb.wallIdBound(); w++)
		if (m_bb.hasWall(w)) m_wallOrder.push_back(w);
	for (const Id w : m_wallOrder)
		if (m_bb.hasWall(w)) visit(moves::Target::Wall, w);
	prune();
}

void BlackboardSampler::visit(moves::Target target, Id id)
{
	const auto alive = [&] {
		return target == moves::Target::Table ? m_bb.hasTable(id)
			   : target == moves::Target::Leg ? m_bb.hasLeg(id)
											   : m_bb.hasWall(id);
	};
	const double u = m_rng.uniform();
	for (size_t k = 0; k < m_moves.entries().size(); k++)
	{
		const moves::MoveEntry& e = m_moves.entries()[k];
		if (e.target != target) continue;
		const int offers = m_ctx.greedy() ? e.polishRepeats : 1;
		for (int i = 0; i < offers && alive(); i++)
			if (e.offered(m_ctx, u))
			{
				m_ctx.entry = k;
				e.visit(m_ctx, id);
			}
	}
}

// Keep only what explains a shapelet directly or shares an ancestor with something that does.
// A removal changes the board without a move: the next checkpoint scores it.
void BlackboardSampler::prune()
{
	const size_t before = m_bb.legCount() + m_bb.tableCount() + m_bb.wallCount();
	m_legSupported.assign(static_cast<size_t>(m_bb.legIdBound()), 0);
	m_tableSupported.assign(static_cast<size_t>(m_bb.tableIdBound()), 0);
	for (Id l = 0; l < m_bb.legIdBound(); l++)
		if (m_bb.hasLeg(l) && m_bb.explains(l)) m_legSupported[l] = 1;
	for (Id l = 0; l < m_bb.legIdBound(); l++)
		if (m_bb.hasLeg(l) && m_legSupported[l] && m_bb.leg(l).parent != NONE)
			m_tableSupported[m_bb.leg(l).parent] = 1;
	for (Id l = 0; l < m_bb.legIdBound(); l++)
	{
		if (!m_bb.hasLeg(l) || m_legSupported[l]) continue;
		const Id parent = m_bb.leg(l).parent;
		if (parent == NONE || !m_tableSupported[parent]) m_bb.removeLeg(l);
	}
	for (Id t = 0; t < m_bb.tableIdBound(); t++)
		if (m_bb.hasTable(t) && !m_tableSupported[t]) m_bb.removeTable(t);
	for (Id w = 0; w < m_bb.wallIdBound(); w++)
		if (m_bb.hasWall(w) && !m_bb.wallExplains(w)) m_bb.removeWall(w);
	if (m_bb.legCount() + m_bb.tableCount() + m_bb.wallCount() == before) return;
	m_scoredAfter = NOT_SCORED;
	m_ctx.changed();
}

// The wall whose link gain for unexplained shapelet s (eq. 22 against the null cause) beats
// `gain` most, or NONE; raises `gain` to it.
Id BlackboardSampler::bestWallFor(size_t s, double& gain) const
{
	Id best = NONE;
	for (Id w = 0; w < m_bb.wallIdBound(); w++)
	{
		if (!m_bb.hasWall(w)) continue;
		const double g = model::logNoisyOr(model::logShapeletGivenWall(m_bb.shapelets()[s], m_bb.wall(w), m_bb.wallFrame(w), m_model),
										   model::logShapeletNull(m_model)) -
						 model::logShapeletNull(m_model);
		if (g > gain) gain = g, best = w;
	}
	return best;
}
}  // namespace whiskermap::inference
