#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/TableProposals.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace whiskermap::inference
{
using model::Id;
using model::Leg;
using model::NONE;
using model::Table;

namespace
{
/** Weight of "stay near the current centre" in a free leg's refit: it only fixes the
 *  position along a face when the contacts leave it open (PoseFit.h). */
constexpr double FREE_LEG_PULL = 1e-3;
bool greedy(double beta) { return std::isinf(beta); }
}  // namespace

BlackboardSampler::BlackboardSampler(const model::ModelParams& model, const SamplerParams& params)
	: m_model(model), m_params(params), m_bb(model), m_backup(model), m_best(model)
{
}

StepResult BlackboardSampler::step(
	const std::vector<obs::Shapelet>& shapelets, uint64_t seed, int snapshotTemperature)
{
	m_bb.reset(shapelets);
	StepResult result;
	run(result, seed, snapshotTemperature);
	return result;
}

StepResult BlackboardSampler::anneal(const model::Blackboard& start, uint64_t seed, int snapshotTemperature)
{
	m_bb = start;
	StepResult result;
	m_result = &result;
	m_rng.seed(seed);
	associate();
	checkpoint(result);  // the map as it was, with the new contacts associated: the first candidate
	result.initialLogPosterior = result.logPosterior;
	run(result, seed ^ 0x5DEECE66Dull, snapshotTemperature);
	return result;
}

void BlackboardSampler::run(StepResult& result, uint64_t seed, int snapshotTemperature)
{
	m_result = &result;
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
		m_searchPoses = i + 1 == m_params.polish_sweeps;  // the pose search: last sweep only
		sweep(std::numeric_limits<double>::infinity());
		checkpoint(result);
	}
	result.map = m_best.compact();
	m_result = nullptr;
}

// Data association first: each shapelet without a leg takes the best of linking to a nearby
// leg (which refits) or a new leg of its own, when that beats leaving it unexplained.
void BlackboardSampler::associate()
{
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
	{
		if (m_bb.shapeletParent(s) != NONE) continue;
		legsNearShapelet(s, m_candidates);
		Id bestLeg = NONE;
		double bestGain = 0;
		for (const Id l : m_candidates)
		{
			const Leg old = m_bb.leg(l);
			double gain = model::logShapeletLinkGain(m_bb, s, l);
			m_bb.setShapeletParent(s, l);
			refitInPlace(l, gain);
			m_bb.setShapeletParent(s, NONE);
			m_bb.setLeg(l, old);
			if (gain > bestGain) bestGain = gain, bestLeg = l;
		}
		const Id id = m_bb.addLeg(newLegFor(s));
		m_bb.setShapeletParent(s, id);
		if (model::logOddsLeg(m_bb, id) > bestGain) continue;  // the new leg stays
		m_bb.removeLeg(id);
		if (bestLeg == NONE) continue;
		m_bb.setShapeletParent(s, bestLeg);
		double ignored = 0;
		refitInPlace(bestLeg, ignored);
	}
}

void BlackboardSampler::checkpoint(StepResult& result)
{
	const double lp = model::logJoint(m_bb);
	if (lp <= result.logPosterior) return;
	result.logPosterior = lp;
	m_best = m_bb;
}

// One pass of Algorithm 1's body at inverse temperature beta, then the prune.
void BlackboardSampler::sweep(double beta)
{
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
		if (m_bb.shapeletParent(s) == NONE) prime(s, beta);

	m_tableOrder.clear();
	m_legOrder.clear();
	for (Id t = 0; t < m_bb.tableIdBound(); t++)
		if (m_bb.hasTable(t) && !m_bb.tableDormant(t)) m_tableOrder.push_back(t);
	for (Id l = 0; l < m_bb.legIdBound(); l++)
		if (m_bb.hasLeg(l) && !m_bb.legDormant(l)) m_legOrder.push_back(l);
	for (const Id t : m_tableOrder)
		if (m_bb.hasTable(t)) visitTable(t, beta);
	for (const Id l : m_legOrder)
		if (m_bb.hasLeg(l)) visitLeg(l, beta);
	prune();
}

bool BlackboardSampler::accept(Move m, double logOdds, double beta)
{
	const auto i = static_cast<size_t>(m);
	m_result->proposed[i]++;
	const bool yes = draw(logOdds, beta);
	m_result->accepted[i] += yes;
	return yes;
}

bool BlackboardSampler::draw(double logOdds, double beta)
{
	if (greedy(beta)) return logOdds > 0;
	return uniform() < model::annealedAcceptance(logOdds, beta);
}

// Q(pa(S)): an existing leg whose perimeter is near S, or a new leg with S on its face.
void BlackboardSampler::prime(size_t s, double beta)
{
	legsNearShapelet(s, m_candidates);
	if (!m_candidates.empty() && uniform() < m_params.existing_leg_probability)
	{
		proposeLink(s, m_candidates[pick(m_candidates.size())], Move::Priming, beta);
		return;
	}
	const Id id = m_bb.addLeg(newLegFor(s));
	m_bb.setShapeletParent(s, id);
	if (!accept(Move::Priming, model::logOddsLeg(m_bb, id), beta)) m_bb.removeLeg(id);
}

// The contact lies on the leg's face with outward normal theta_S: the centre is half a leg
// width inward along -normal, anywhere along the face.
Leg BlackboardSampler::newLegFor(size_t s)
{
	const obs::Shapelet& sh = m_bb.shapelets()[s];
	const double w = m_model.leg_width, nx = std::cos(sh.normal), ny = std::sin(sh.normal);
	const double along = alongFace(s);
	Leg l;
	l.x = sh.x - nx * w / 2 - ny * along + m_params.leg_position_noise * gaussian();
	l.y = sh.y - ny * w / 2 + nx * along + m_params.leg_position_noise * gaussian();
	l.theta = sh.normal + m_params.leg_angle_noise * gaussian();
	l.wx = l.wy = w;
	l.texture = sh.texture;
	return l;
}

// Split: contact s leaves leg `from` (which refits to the rest) for a new leg of its own.
// The reverse of a link; exact local change of logJoint, undone on rejection.
void BlackboardSampler::proposeSplit(size_t s, double beta)
{
	const Id from = m_bb.shapeletParent(s);
	const Leg old = m_bb.leg(from);
	double gain = -model::logShapeletLinkGain(m_bb, s, from);
	m_bb.setShapeletParent(s, NONE);
	refitInPlace(from, gain);
	const Id id = m_bb.addLeg(newLegFor(s));
	m_bb.setShapeletParent(s, id);
	if (accept(Move::Child, gain + model::logOddsLeg(m_bb, id), beta)) return;
	m_bb.removeLeg(id);
	m_bb.setLeg(from, old);
	m_bb.setShapeletParent(s, from);
}

// Moves, in the order of the thresholds: 0 death, 1 new parent, 2 child, 3 refit, 4 parent.
void BlackboardSampler::visitTable(Id t, double beta)
{
	const double u = uniform();
	const bool all = greedy(beta);
	if ((all || u < m_params.r1) && m_bb.hasTable(t)) proposeTableDeath(t, beta);
	// A table may miss up to 3 legs: the greedy polish offers each empty corner.
	for (int i = 0; i < (all ? 3 : 1) && m_bb.hasTable(t); i++)
		if (all || (u >= m_params.r2 && u < m_params.r3)) proposeTableChild(t, beta);
	if ((all || (u >= m_params.r3 && u < m_params.r4)) && m_bb.hasTable(t)) proposeTableRefit(t, beta);
	// Tables have no parents: the reparent and parent draws propose nothing.
}

void BlackboardSampler::visitLeg(Id l, double beta)
{
	const double u = uniform();
	const bool all = greedy(beta);
	// A leg holding folded contacts never dies: they would be lost (doc/map-plugin.md).
	if ((all || u < m_params.r1) && m_bb.hasLeg(l) && m_bb.evidence(l).empty() &&
		accept(Move::Death, -model::logOddsLeg(m_bb, l), beta))
		m_bb.removeLeg(l);
	if ((all || (u >= m_params.r1 && u < m_params.r2)) && m_bb.hasLeg(l)) proposeLegReparent(l, beta);
	if ((all || (u >= m_params.r2 && u < m_params.r3)) && m_bb.hasLeg(l)) proposeLegChild(l, beta);
	if ((all || (u >= m_params.r3 && u < m_params.r4)) && m_bb.hasLeg(l)) proposeLegRefit(l, beta);
	if ((all || u >= m_params.r4) && m_bb.hasLeg(l)) proposeTableForLeg(l, beta);
	if (all && m_searchPoses && m_bb.hasLeg(l)) searchLegPose(l);
}

// Death of a table takes the legs it invented (they explain nothing; the prune would remove
// them), so the move is judged on the whole change. Undone exactly on rejection.
void BlackboardSampler::proposeTableDeath(Id t, double beta)
{
	m_backup = m_bb;
	if (!accept(Move::Death, removeTableAndOrphans(m_bb, t, m_orphans), beta)) m_bb = m_backup;
}

// A new parent for a leg: any other table with a corner within the gate, or none.
void BlackboardSampler::proposeLegReparent(Id l, double beta)
{
	const Leg& leg = m_bb.leg(l);
	m_candidates.clear();
	if (leg.parent != NONE) m_candidates.push_back(NONE);
	const double reach = std::hypot(m_model.table_length, m_model.table_width) / 2 + m_model.parent_gate;
	m_bb.forEachTableNear(leg.x, leg.y, reach, [&](Id t) {
		if (t == leg.parent) return;
		double cx = 0, cy = 0;
		const int corner = model::logLegGivenTable(leg, m_bb.table(t), m_model).corner;
		model::tableCorner(m_bb.table(t), corner, m_model, cx, cy);
		if (std::hypot(cx - leg.x, cy - leg.y) <= m_model.parent_gate) m_candidates.push_back(t);
	});
	if (m_candidates.empty()) return;
	const Id to = m_candidates[pick(m_candidates.size())];
	const double gain = model::logLegLinkGain(m_bb, l, to) - model::logLegLinkGain(m_bb, l, leg.parent);
	if (accept(Move::Reparent, gain, beta)) m_bb.setLegParent(l, to);
}

// Q(ch(L) | L): a nearby shapelet not yet explained by L moves to L, or (half the time, if
// L explains two or more) one of L's contacts leaves it for a new leg.
void BlackboardSampler::proposeLegChild(Id l, double beta)
{
	m_candidates = m_bb.shapeletsOf(l);
	// A split needs a contact to leave and something to stay: another contact or folded evidence.
	if (!m_candidates.empty() && m_candidates.size() + !m_bb.evidence(l).empty() >= 2 &&
		(greedy(beta) || uniform() < 0.5))
	{
		proposeSplit(static_cast<size_t>(m_candidates[pick(m_candidates.size())]), beta);
		if (!greedy(beta)) return;
	}
	if (greedy(beta) || uniform() < m_params.merge_probability)
	{
		mergeCandidates(l);
		if (greedy(beta))
		{
			for (size_t i = 0; i < m_mergeable.size() && m_bb.hasLeg(l); i++)
				if (m_bb.hasLeg(m_mergeable[i])) proposeMerge(l, m_mergeable[i], beta);
			if (!m_bb.hasLeg(l)) return;
		}
		else if (!m_mergeable.empty())
		{
			proposeMerge(l, m_mergeable[pick(m_mergeable.size())], beta);
			return;
		}
	}
	const auto& leg = m_bb.leg(l);
	const model::OrientedRect r = model::legRect(leg);
	m_candidates.clear();
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
		if (m_bb.shapeletParent(s) != l &&
			r.perimeter(m_bb.shapelets()[s].x, m_bb.shapelets()[s].y).distance <= m_model.parent_gate)
			m_candidates.push_back(static_cast<Id>(s));
	if (m_candidates.empty()) return;
	proposeLink(static_cast<size_t>(m_candidates[pick(m_candidates.size())]), l, Move::Child, beta);
}

// Shapelet s moves to leg l, l refits to its contacts (and corner), and the leg s leaves is
// dropped if it is then a free leg explaining nothing (the prune would drop it). Exact local
// change of logJoint, step by step; undone on rejection.
void BlackboardSampler::proposeLink(size_t s, Id l, Move m, double beta)
{
	const Id from = m_bb.shapeletParent(s);
	const Leg old = m_bb.leg(l);
	double gain = model::logShapeletLinkGain(m_bb, s, l) - model::logShapeletLinkGain(m_bb, s, from);
	m_bb.setShapeletParent(s, l);
	refitInPlace(l, gain);
	const bool drop = from != NONE && m_bb.leg(from).parent == NONE && !m_bb.explains(from);
	if (drop) gain -= model::logOddsLeg(m_bb, from);
	if (accept(m, gain, beta))
	{
		if (drop) m_bb.removeLeg(from);
		return;
	}
	m_bb.setLeg(l, old);
	m_bb.setShapeletParent(s, from);
}

void BlackboardSampler::mergeCandidates(Id l)
{
	m_mergeable.clear();
	const Leg& leg = m_bb.leg(l);
	// Two contacts one leg explains are within its diagonal plus two gates of each other, so
	// the leg centres are within that plus one half-diagonal each.
	const double w = m_model.leg_width, reach = 2 * w * std::sqrt(2.0) + 2 * m_model.parent_gate;
	m_bb.forEachLegNear(leg.x, leg.y, reach, [&](Id o) {
		if (o != l && m_bb.explains(o)) m_mergeable.push_back(o);
	});
}

// Merge: all contacts of `other` move to l, other is removed (its local log-odds, eq. 20,
// with its contacts unlinked), the contacts link to l one by one, and l refits to all its
// contacts. Exact local change of logJoint; undone exactly on rejection.
bool BlackboardSampler::proposeMerge(Id l, Id other, double beta)
{
	m_moved.assign(m_bb.shapeletsOf(other).begin(), m_bb.shapeletsOf(other).end());
	if (!m_bb.explains(other)) return false;
	const Leg oldL = m_bb.leg(l), oldOther = m_bb.leg(other);
	const model::LegEvidence oldEvidence = m_bb.evidence(l), otherEvidence = m_bb.evidence(other);
	double gain = -model::logOddsLeg(m_bb, other);
	m_bb.removeLeg(other);
	for (const Id s : m_moved)
	{
		gain += model::logShapeletLinkGain(m_bb, static_cast<size_t>(s), l);
		m_bb.setShapeletParent(static_cast<size_t>(s), l);
	}
	if (!otherEvidence.empty())
	{
		// The folded contacts move too: log-odds of l before and after (eq. 20) differ by them.
		gain -= model::logOddsLeg(m_bb, l);
		model::LegEvidence merged = oldEvidence;
		merged.merge(otherEvidence);
		m_bb.setEvidence(l, merged);
		gain += model::logOddsLeg(m_bb, l);
	}
	const bool fitted = refitInPlace(l, gain);
	if (fitted && accept(Move::Child, gain, beta)) return true;
	m_bb.setLeg(l, oldL);
	m_bb.setEvidence(l, oldEvidence);
	const Id back = m_bb.addLeg(oldOther, otherEvidence);
	for (const Id s : m_moved) m_bb.setShapeletParent(static_cast<size_t>(s), back);
	return false;
}

// Greedy compass search on (x, y, yaw) of leg l (PoseFit's searchLegPose), counted as a refit.
void BlackboardSampler::searchLegPose(Id l)
{
	const double gain = inference::searchLegPose(m_bb, l, 1e-9);
	m_result->proposed[static_cast<size_t>(Move::Refit)]++;
	m_result->accepted[static_cast<size_t>(Move::Refit)] += gain > 0;
}

// Q(ch(T) | T): the missing leg at a uniformly chosen empty corner, exactly as eq. 6 expects.
void BlackboardSampler::proposeTableChild(Id t, double beta)
{
	const model::CornerCounts counts = m_bb.cornerCounts(t);
	int empty[4], n = 0;
	for (int c = 0; c < 4; c++)
		if (counts[c] == 0) empty[n++] = c;
	if (n == 0) return;
	const Table& table = m_bb.table(t);
	Leg l;
	model::tableCorner(table, empty[pick(static_cast<size_t>(n))], m_model, l.x, l.y);
	l.theta = table.theta;
	l.wx = l.wy = table.leg_width;
	l.texture = table.texture;
	l.parent = t;
	const Id id = m_bb.addLeg(l);
	if (!accept(Move::Child, model::logOddsLeg(m_bb, id), beta)) m_bb.removeLeg(id);
}

// Q(pa(L) | L): a table of the known size with the leg at one of its 4 corners, in one of
// the 2 yaws (mod pi) consistent with the leg's yaw (mod pi/2): 8 candidates. Data-driven:
// candidate i is drawn with weight ADOPT_WEIGHT^n_i, n_i the other legs it would adopt
// (legs within the parent gate of one of its still empty corners), and the new table
// adopts them in the same move, so the move is judged on all the evidence it explains.
void BlackboardSampler::proposeTableForLeg(Id l, double beta)
{
	constexpr double ADOPT_WEIGHT = 4;
	m_tables.clear();
	for (int i = 0; i < 8; i++) m_tables.push_back(tableWithLegAt(m_model, m_bb.leg(l), i / 2, i % 2 ? M_PI_2 : 0.0));
	tablesForPairs(m_bb, l, m_tables);
	m_weights.clear();
	double total = 0;
	for (const Table& t : m_tables)
		total += m_weights.emplace_back(std::pow(ADOPT_WEIGHT, static_cast<double>(adoptable(m_bb, t, l, m_candidates))));
	size_t choice = 0;
	for (double u = uniform() * total; choice + 1 < m_tables.size() && u >= m_weights[choice]; choice++)
		u -= m_weights[choice];
	// The chosen table, fitted to all the legs it adopts (PoseFit.h), then adopting anew.
	Table chosen = m_tables[choice];
	adoptable(m_bb, chosen, l, m_candidates);  // fills m_candidates with the adopted legs
	m_candidates.push_back(l);
	m_fitLegs.clear();
	m_fitCorners.clear();
	for (const Id a : m_candidates)
	{
		m_fitLegs.push_back(&m_bb.leg(a));
		m_fitCorners.push_back(model::logLegGivenTable(m_bb.leg(a), chosen, m_model).corner);
	}
	if (m_candidates.size() > 1) chosen = fitTable(m_model, chosen, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
	adoptable(m_bb, chosen, l, m_candidates);
	m_candidates.push_back(l);

	// Tables the adopted legs leave without any leg that explains a shapelet are pruned at
	// the end of the sweep anyway: the move removes them itself, so it is judged on that.
	m_abandoned.clear();
	for (const Id a : m_candidates)
	{
		const Id p = m_bb.leg(a).parent;
		if (p != NONE && !hasSupportedLeg(p, m_candidates) &&
			std::find(m_abandoned.begin(), m_abandoned.end(), p) == m_abandoned.end())
			m_abandoned.push_back(p);
	}
	if (!m_abandoned.empty()) m_backup = m_bb;

	// Exact change of logJoint, one local step at a time: unlink the adopted legs, add the
	// table with them all as children (eq. 20 of the new table), remove abandoned tables.
	double logOdds = 0;
	m_oldParents.clear();
	for (const Id a : m_candidates)
	{
		m_oldParents.push_back(m_bb.leg(a).parent);
		logOdds -= model::logLegLinkGain(m_bb, a, m_bb.leg(a).parent);
		m_bb.setLegParent(a, NONE);
	}
	const Id id = m_bb.addTable(chosen);
	for (const Id a : m_candidates) m_bb.setLegParent(a, id);
	logOdds += model::logOddsTable(m_bb, id);
	for (const Id p : m_abandoned) logOdds += removeTableAndOrphans(m_bb, p, m_orphans);
	if (accept(Move::Parent, logOdds, beta)) return;
	if (!m_abandoned.empty())
	{
		m_bb = m_backup;
		return;
	}
	m_bb.removeTable(id);
	for (size_t i = 0; i < m_candidates.size(); i++) m_bb.setLegParent(m_candidates[i], m_oldParents[i]);
}

bool BlackboardSampler::hasSupportedLeg(Id table, const std::vector<Id>& except) const
{
	for (const Id l : m_bb.legsOf(table))
		if (m_bb.explains(l) && std::find(except.begin(), except.end(), l) == except.end()) return true;
	return false;
}

bool BlackboardSampler::fittedLeg(Id l, const Table* t, Leg& out)
{
	const Leg& leg = m_bb.leg(l);
	m_contacts.clear();
	for (const Id s : m_bb.shapeletsOf(l)) m_contacts.push_back(&m_bb.shapelets()[static_cast<size_t>(s)]);
	const model::LegEvidence& evidence = m_bb.evidence(l);
	if (m_contacts.empty() && evidence.empty() && !t) return false;
	double qx = leg.x, qy = leg.y, pull = FREE_LEG_PULL;
	if (t)
	{
		model::tableCorner(*t, model::logLegGivenTable(leg, *t, m_model).corner, m_model, qx, qy);
		pull = 1;
	}
	out = fitLeg(m_model, m_contacts.data(), m_contacts.size(), t, qx, qy, pull, &evidence);
	out.parent = leg.parent;
	const model::OrientedRect r = model::legRect(out);
	for (const obs::Shapelet* s : m_contacts)
		if (r.perimeter(s->x, s->y).distance > m_model.parent_gate) return false;
	return !t || std::hypot(out.x - qx, out.y - qy) <= m_model.parent_gate;
}

// Moves leg l to its closed-form pose (if valid) and adds the change of logJoint to `gain`:
// local, eq. 20 before and after (the board without the leg is the same).
bool BlackboardSampler::refitInPlace(Id l, double& gain)
{
	Leg fit;
	const Id parent = m_bb.leg(l).parent;
	if (!fittedLeg(l, parent == NONE ? nullptr : &m_bb.table(parent), fit)) return false;
	gain -= model::logOddsLeg(m_bb, l);
	m_bb.setLeg(l, fit);
	gain += model::logOddsLeg(m_bb, l);
	return true;
}

// Refit of a leg: the closed-form pose for its contacts and its parent's corner.
void BlackboardSampler::proposeLegRefit(Id l, double beta)
{
	const Leg old = m_bb.leg(l);
	double gain = 0;
	if (refitInPlace(l, gain) && !accept(Move::Refit, gain, beta)) m_bb.setLeg(l, old);
}

// Refit of a table: twice (fit the table to its legs that explain shapelets, then refit
// those legs to their contacts and new corners), then its invented legs onto its corners.
// Judged on the exact change of logJoint; undone on rejection.
void BlackboardSampler::proposeTableRefit(Id t, double beta)
{
	m_savedLegs.clear();
	for (const Id l : m_bb.legsOf(t)) m_savedLegs.emplace_back(l, m_bb.leg(l));
	const Table old = m_bb.table(t);
	const double before = model::logJointAround(m_bb, t);
	bool valid = true;
	for (int round = 0; round < 2 && valid; round++)
	{
		m_fitLegs.clear();
		m_fitCorners.clear();
		for (const auto& [l, saved] : m_savedLegs)
			if (m_bb.explains(l)) m_fitLegs.push_back(&m_bb.leg(l)), m_fitCorners.push_back(m_bb.leg(l).corner);
		if (m_fitLegs.empty()) return;  // nothing to fit (and nothing changed yet)
		m_bb.setTable(t, fitTable(m_model, old, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size()));
		for (const auto& [l, saved] : m_savedLegs)
		{
			Leg fit;
			if (!m_bb.explains(l)) continue;
			valid = valid && fittedLeg(l, &m_bb.table(t), fit);
			if (valid) m_bb.setLeg(l, fit);
		}
	}
	const Table& now = m_bb.table(t);
	for (const auto& [l, saved] : m_savedLegs)
	{
		if (m_bb.explains(l)) continue;
		Leg moved = saved;
		model::tableCorner(now, saved.corner, m_model, moved.x, moved.y);
		moved.theta = now.theta;
		m_bb.setLeg(l, moved);
	}
	if (valid && accept(Move::Refit, model::logJointAround(m_bb, t) - before, beta)) return;
	m_bb.setTable(t, old);
	for (const auto& [l, saved] : m_savedLegs) m_bb.setLeg(l, saved);
}

// Where along its face the contact of shapelet s lies, from the leg centre. Uniform, unless
// another shapelet nearby has a normal a quarter turn away: then both lie on adjacent faces
// of one square leg, which fixes the offset.
double BlackboardSampler::alongFace(size_t s)
{
	const double w = m_model.leg_width, gate = 3 * m_model.sigma_theta;
	const obs::Shapelet& a = m_bb.shapelets()[s];
	for (const obs::Shapelet& b : m_bb.shapelets())
	{
		const double turn = core::angleDiff(b.normal, a.normal, 2 * M_PI);
		if (std::hypot(b.x - a.x, b.y - a.y) > 1.5 * w || std::abs(std::abs(turn) - M_PI_2) > gate) continue;
		const double side = turn > 0 ? 1 : -1;  // b's normal = a's tangent * side
		const double tx = -std::sin(a.normal), ty = std::cos(a.normal);
		const double offset = side * ((b.x - a.x) * tx * side + (b.y - a.y) * ty * side - w / 2);
		return std::clamp(offset, -w / 2, w / 2);
	}
	return (uniform() - 0.5) * w;
}

// Keep only what explains a shapelet directly or shares an ancestor with something that does.
void BlackboardSampler::prune()
{
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
}

void BlackboardSampler::legsNearShapelet(size_t s, std::vector<Id>& out) const
{
	const obs::Shapelet& sh = m_bb.shapelets()[s];
	out.clear();
	m_bb.forEachLegNear(sh.x, sh.y, m_bb.maxLegRadius() + m_model.parent_gate, [&](Id l) {
		if (model::legRect(m_bb.leg(l)).perimeter(sh.x, sh.y).distance <= m_model.parent_gate)
			out.push_back(l);
	});
}

double BlackboardSampler::uniform() { return static_cast<double>(m_rng() >> 11) * 0x1.0p-53; }

size_t BlackboardSampler::pick(size_t n) { return static_cast<size_t>(uniform() * static_cast<double>(n)); }

// Box-Muller from our own uniforms: the same numbers on every standard library.
double BlackboardSampler::gaussian()
{
	const double u1 = 1.0 - uniform(), u2 = uniform();
	return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
}
}  // namespace whiskermap::inference
