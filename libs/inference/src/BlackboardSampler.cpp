#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::inference
{
using model::Id;
using model::Leg;
using model::NONE;
using model::Table;

BlackboardSampler::BlackboardSampler(const model::ModelParams& model, const SamplerParams& params)
	: m_model(model), m_params(params), m_bb(model), m_backup(model)
{
}

StepResult BlackboardSampler::step(
	const std::vector<obs::Shapelet>& shapelets, uint64_t seed, int snapshotTemperature)
{
	StepResult result;
	m_result = &result;
	m_rng.seed(seed);
	m_bb.reset(shapelets);
	const auto& betas = m_params.schedule.betas();
	for (size_t k = 0; k < betas.size(); k++)
	{
		const bool coldest = k + 1 == betas.size();
		const int sweeps = coldest ? m_params.coldest_sweeps : m_params.sweeps_per_temperature;
		for (int i = 0; i < sweeps; i++)
		{
			sweep(betas[k]);
			if (!coldest) continue;
			const double lp = model::logJoint(m_bb);
			if (lp > result.logPosterior)
			{
				result.logPosterior = lp;
				result.map = m_bb.compact();
			}
		}
		if (static_cast<int>(k) == snapshotTemperature) result.snapshot = m_bb.compact();
	}
	m_result = nullptr;
	return result;
}

// One pass of Algorithm 1's body at inverse temperature beta, then the prune.
void BlackboardSampler::sweep(double beta)
{
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
		if (m_bb.shapeletParent(s) == NONE) prime(s, beta);

	m_tableOrder.clear();
	m_legOrder.clear();
	for (Id t = 0; t < m_bb.tableIdBound(); t++)
		if (m_bb.hasTable(t)) m_tableOrder.push_back(t);
	for (Id l = 0; l < m_bb.legIdBound(); l++)
		if (m_bb.hasLeg(l)) m_legOrder.push_back(l);
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
	const bool yes = uniform() < model::annealedAcceptance(logOdds, beta);
	m_result->accepted[i] += yes;
	return yes;
}

// Q(pa(S)): an existing leg whose perimeter is near S, or a new leg with S on its face.
void BlackboardSampler::prime(size_t s, double beta)
{
	legsNearShapelet(s, m_candidates);
	if (!m_candidates.empty() && uniform() < m_params.existing_leg_probability)
	{
		const Id l = m_candidates[pick(m_candidates.size())];
		if (accept(Move::Priming, model::logShapeletLinkGain(m_bb, s, l), beta))
			m_bb.setShapeletParent(s, l);
		return;
	}
	// The contact lies on the leg's face with outward normal theta_S: the centre is half a
	// leg width inward along -normal, anywhere along the face.
	const obs::Shapelet& sh = m_bb.shapelets()[s];
	const double w = m_model.leg_width, nx = std::cos(sh.normal), ny = std::sin(sh.normal);
	const double along = alongFace(s);
	Leg l;
	l.x = sh.x - nx * w / 2 - ny * along + m_params.leg_position_noise * gaussian();
	l.y = sh.y - ny * w / 2 + nx * along + m_params.leg_position_noise * gaussian();
	l.theta = sh.normal + m_params.leg_angle_noise * gaussian();
	l.wx = l.wy = w;
	l.texture = sh.texture;
	const Id id = m_bb.addLeg(l);
	m_bb.setShapeletParent(s, id);
	if (!accept(Move::Priming, model::logOddsLeg(m_bb, id), beta)) m_bb.removeLeg(id);
}

void BlackboardSampler::visitTable(Id t, double beta)
{
	const double u = uniform();
	if (u < m_params.r1)
	{
		if (accept(Move::Death, -model::logOddsTable(m_bb, t), beta)) m_bb.removeTable(t);
	}
	else if (u >= m_params.r2 && u < m_params.r3)
		proposeTableChild(t, beta);
	// Tables have no parents: the reparent and parent draws propose nothing.
}

void BlackboardSampler::visitLeg(Id l, double beta)
{
	const double u = uniform();
	if (u < m_params.r1)
	{
		if (accept(Move::Death, -model::logOddsLeg(m_bb, l), beta)) m_bb.removeLeg(l);
	}
	else if (u < m_params.r2)
		proposeLegReparent(l, beta);
	else if (u < m_params.r3)
		proposeLegChild(l, beta);
	else
		proposeTableForLeg(l, beta);
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

// Q(ch(L) | L): a nearby shapelet not yet explained by L moves to L.
void BlackboardSampler::proposeLegChild(Id l, double beta)
{
	const auto& leg = m_bb.leg(l);
	const model::OrientedRect r = model::legRect(leg);
	m_candidates.clear();
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
		if (m_bb.shapeletParent(s) != l &&
			r.perimeter(m_bb.shapelets()[s].x, m_bb.shapelets()[s].y).distance <= m_model.parent_gate)
			m_candidates.push_back(static_cast<Id>(s));
	if (m_candidates.empty()) return;
	const auto s = static_cast<size_t>(m_candidates[pick(m_candidates.size())]);
	const double gain =
		model::logShapeletLinkGain(m_bb, s, l) - model::logShapeletLinkGain(m_bb, s, m_bb.shapeletParent(s));
	if (accept(Move::Child, gain, beta)) m_bb.setShapeletParent(s, l);
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
	Table candidates[8];
	double weights[8], total = 0;
	for (int i = 0; i < 8; i++)
	{
		candidates[i] = tableWithLegAt(m_bb.leg(l), i / 2, i % 2 ? M_PI_2 : 0.0);
		weights[i] = std::pow(ADOPT_WEIGHT, static_cast<double>(adoptable(candidates[i], l)));
		total += weights[i];
	}
	int choice = 0;
	for (double u = uniform() * total; choice < 7 && u >= weights[choice]; choice++) u -= weights[choice];
	adoptable(candidates[choice], l);  // fills m_candidates with the adopted legs
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
	const Id id = m_bb.addTable(candidates[choice]);
	for (const Id a : m_candidates) m_bb.setLegParent(a, id);
	logOdds += model::logOddsTable(m_bb, id);
	for (const Id p : m_abandoned) logOdds += removeTableAndOrphans(p);
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
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
	{
		const Id l = m_bb.shapeletParent(s);
		if (l != NONE && m_bb.leg(l).parent == table && std::find(except.begin(), except.end(), l) == except.end())
			return true;
	}
	return false;
}

double BlackboardSampler::removeTableAndOrphans(Id table)
{
	double logOdds = -model::logOddsTable(m_bb, table);
	m_orphans.clear();
	for (Id l = 0; l < m_bb.legIdBound(); l++)
		if (m_bb.hasLeg(l) && m_bb.leg(l).parent == table) m_orphans.push_back(l);
	m_bb.removeTable(table);
	for (const Id l : m_orphans)
	{
		logOdds -= model::logOddsLeg(m_bb, l);
		m_bb.removeLeg(l);
	}
	return logOdds;
}

Table BlackboardSampler::tableWithLegAt(const Leg& leg, int corner, double turn) const
{
	Table t;
	t.theta = leg.theta + turn;
	t.leg_width = m_model.leg_width;
	t.texture = m_model.texture;
	double cx = 0, cy = 0;  // the corner of a table centred at the origin
	model::tableCorner(t, corner, m_model, cx, cy);
	t.x = leg.x - cx;
	t.y = leg.y - cy;
	return t;
}

size_t BlackboardSampler::adoptable(const Table& t, Id l)
{
	bool taken[4] = {false, false, false, false};
	taken[model::logLegGivenTable(m_bb.leg(l), t, m_model).corner] = true;
	m_candidates.clear();
	const double reach = std::hypot(m_model.table_length, m_model.table_width) / 2 + m_model.parent_gate;
	m_bb.forEachLegNear(t.x, t.y, reach, [&](Id o) {
		if (o == l) return;
		const Leg& leg = m_bb.leg(o);
		const int c = model::logLegGivenTable(leg, t, m_model).corner;
		double cx = 0, cy = 0;
		model::tableCorner(t, c, m_model, cx, cy);
		if (taken[c] || std::hypot(cx - leg.x, cy - leg.y) > m_model.parent_gate) return;
		taken[c] = true;
		m_candidates.push_back(o);
	});
	return m_candidates.size();
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
	for (size_t s = 0; s < m_bb.shapelets().size(); s++)
		if (m_bb.shapeletParent(s) != NONE) m_legSupported[m_bb.shapeletParent(s)] = 1;
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
