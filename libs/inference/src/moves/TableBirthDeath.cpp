#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/TableProposals.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;
using model::Table;

// Death of a table takes the legs it invented (they explain nothing; the prune would remove
// them), so the move is judged on the whole change. Undone exactly on rejection.
// Under stochastic refits its reverse is the stochastic birth from the table's canonical leg
// (its leg of least id): the probability of that birth proposing the table's cell with exactly
// its legs, on the board after the death.
Proposal TableBirthDeath::death(MoveContext& ctx, Id t)
{
	m_backup = ctx.bb;
	m_restore = true;
	m_table = NONE;
	m_invented.clear();
	const Table old = ctx.bb.table(t);
	const bool completed = m_complete && invented(ctx, t);  // the orphans are the completed birth's
	m_legs.clear();
	for (const Id l : ctx.bb.legsOf(t))
		if (ctx.bb.explains(l)) m_legs.push_back(l);
	Proposal p{Move::Death, removeTableAndOrphans(ctx.bb, t, m_orphans)};
	p.logReverse = -std::numeric_limits<double>::infinity();
	if (!ctx.stochasticRefits() || (!m_orphans.empty() && !completed) || m_legs.empty() ||
		ctx.mp.cornersTighterThanReadings() ||
		old.d_length != 0 || old.d_width != 0 || old.leg_width != ctx.mp.legWidthOf(old.cls) ||
		old.texture != ctx.mp.textureOf(old.cls))
		return p;  // the birth makes no invented leg, resizes none and proposes class-size tables
	for (const Id l : m_legs)
		if (ctx.bb.leg(l).wx != old.leg_width || ctx.bb.leg(l).wy != old.leg_width) return p;
	std::sort(m_legs.begin(), m_legs.end());
	weighCandidates(ctx, m_legs.front());
	p.logReverse = logDrawnBirth(ctx, m_legs.front(), old, m_legs);
	return p;
}

std::optional<Proposal> TableBirthDeath::rebirth(MoveContext& ctx, Id t)
{
	Proposal p = death(ctx, t);  // the board is now without t (and, completed, its invented legs)
	if (!std::isfinite(p.logReverse))
	{
		finish(ctx, false);
		return std::nullopt;
	}
	const std::vector<Id> legs = m_legs;  // sorted: legs.front() is the canonical leg
	double logForward = 0;
	const Table chosen = drawCandidate(ctx, legs.front(), logForward);
	const Table drawn = ctx.drawnTable(outcome(ctx, legs.front(), chosen, m_candidates), false);
	std::sort(m_candidates.begin(), m_candidates.end());
	bool sameWidth = true;  // else place() would refit the legs (and its own backup would replace the death's)
	for (const Id l : legs) sameWidth = sameWidth && ctx.bb.leg(l).wx == drawn.leg_width && ctx.bb.leg(l).wy == drawn.leg_width;
	if (m_candidates != legs || !sameWidth)
	{
		finish(ctx, false);
		return std::nullopt;
	}
	p.logForward = logDrawnBirth(ctx, legs.front(), drawn, legs);
	const Proposal born = place(ctx, drawn);  // adopts free legs at the table's width: nothing to restore
	p.logTarget += born.logTarget;
	invent(ctx, p.logTarget);
	m_restore = true;  // a rejection restores the board before the death
	p.kind = Move::Parent;
	return p;
}

double TableBirthDeath::logDrawnBirth(const MoveContext& ctx, Id l, const Table& table, const std::vector<Id>& legs)
{
	double total = 0, sum = -std::numeric_limits<double>::infinity();
	for (const double w : m_weights) total += w;
	for (size_t i = 0; i < m_tables.size(); i++)
	{
		const Table fitted = outcome(ctx, l, m_tables[i], m_adopted);
		std::sort(m_adopted.begin(), m_adopted.end());
		if (m_adopted == legs && m_weights[i] > 0)
			sum = model::logSumExp(sum, std::log(m_weights[i] / total) + ctx.logTableDrawnAbout(table, fitted, false));
	}
	return sum + 3 * std::log(2 * ctx.mp.delta);  // per eq. 19 cell (doc/sampler.md, "Cells, not densities")
}

// Candidate i is drawn with weight ADOPT_WEIGHT^n_i phi_f,i, n_i the other legs it would adopt
// (legs within the parent gate of one of its still empty corners) and phi_f,i the free-space
// factor (eq. 21, 1 when off) of the legs it implies at its four corners: 8 tables with the
// leg at one of 4 corners in one of the 2 yaws (mod pi) consistent with the leg's yaw (mod
// pi/2), for each class of the catalogue, and the pair tables (each class whose corner
// distances fit the pair). Broad proposals: the 8 tables per class only, drawn uniformly.
Table TableBirthDeath::drawCandidate(MoveContext& ctx, Id l, double& logProbability)
{
	const double total = weighCandidates(ctx, l);
	size_t choice = 0;
	for (double u = ctx.rng.uniform() * total; choice + 1 < m_tables.size() && u >= m_weights[choice]; choice++)
		u -= m_weights[choice];
	logProbability = std::log(m_weights[choice] / total);
	return m_tables[choice];
}

double TableBirthDeath::weighCandidates(const MoveContext& ctx, Id l)
{
	constexpr double ADOPT_WEIGHT = 4;
	m_tables.clear();
	for (int k = 0; k < ctx.mp.classCount(); k++)
		for (int i = 0; i < 8; i++)
			m_tables.push_back(tableWithLegAt(ctx.mp, ctx.bb.leg(l), i / 2, i % 2 ? M_PI_2 : 0.0, k));
	if (!ctx.broad()) tablesForPairs(ctx.bb, l, m_tables);
	m_weights.clear();
	double total = 0;
	for (const Table& t : m_tables)
		total += m_weights.emplace_back(
			ctx.broad() ? 1.0
						: std::pow(ADOPT_WEIGHT, static_cast<double>(adoptable(ctx.bb, t, l, m_candidates))) *
							  std::exp(ctx.bb.swept().logEmptyCorners(t, {0, 0, 0, 0}, ctx.mp)));
	return total;
}

// The new table adopts the legs in the same move, so the move is judged on all the evidence
// it explains.
// Under stochastic refits the fitted table is drawn about its fit (MoveContext::drawnTable),
// with the legs the fit adopts: logForward sums over the candidates with that outcome, per
// cell; the reverse (the death) exists only for the birth from the table's canonical leg.
Proposal TableBirthDeath::birth(MoveContext& ctx, Id l)
{
	double logForward = 0;
	const Table chosen = drawCandidate(ctx, l, logForward);
	if (!ctx.stochasticRefits())
	{
		Proposal p = birthOf(ctx, l, chosen);
		p.logForward = logForward;
		return p;
	}
	const Table drawn = ctx.drawnTable(outcome(ctx, l, chosen, m_candidates), false);
	m_legs = m_candidates;
	std::sort(m_legs.begin(), m_legs.end());
	logForward = logDrawnBirth(ctx, l, drawn, m_legs);
	Proposal p = place(ctx, drawn);
	p.logForward = logForward;
	if (m_legs.front() != l) p.logReverse = -std::numeric_limits<double>::infinity();
	if (m_complete) invent(ctx, p.logTarget);
	return p;
}

bool TableBirthDeath::invented(const MoveContext& ctx, Id t) const
{
	const model::Blackboard& bb = ctx.bb;
	const Table& table = bb.table(t);
	const model::CornerCounts counts = bb.cornerCounts(t);
	for (const int c : counts)
		if (c == 0) return false;
	for (const Id l : bb.legsOf(t))
	{
		const model::Leg& leg = bb.leg(l);
		if (!bb.explains(l) &&
			(counts[static_cast<size_t>(leg.corner)] != 1 || !LegBirthDeath::standsAtCorner(ctx.mp, leg, table)))
			return false;
	}
	return true;
}

void TableBirthDeath::invent(MoveContext& ctx, double& logTarget)
{
	model::Blackboard& bb = ctx.bb;
	const Table& table = bb.table(m_table);
	const model::CornerCounts counts = bb.cornerCounts(m_table);
	for (int c = 0; c < 4; c++)
	{
		if (counts[static_cast<size_t>(c)] != 0) continue;
		m_invented.push_back(bb.addLeg(LegBirthDeath::atCorner(ctx.mp, table, c, m_table)));
		logTarget += model::logOddsLeg(bb, m_invented.back());  // eq. 20, as birthAtCorner
	}
}

Table TableBirthDeath::outcome(const MoveContext& ctx, Id l, Table chosen, std::vector<Id>& adopted)
{
	const model::Blackboard& bb = ctx.bb;
	// The chosen table, fitted to all the legs it adopts (PoseFit.h; not with broad
	// proposals), then adopting anew.
	adoptable(bb, chosen, l, adopted);
	adopted.push_back(l);
	m_fitLegs.clear();
	m_fitCorners.clear();
	for (const Id a : adopted)
	{
		m_fitLegs.push_back(&bb.leg(a));
		m_fitCorners.push_back(model::logLegGivenTable(bb.leg(a), chosen, ctx.mp).corner);
	}
	if (adopted.size() > 1 && !ctx.broad()) chosen = fitTable(ctx.mp, chosen, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
	adoptable(bb, chosen, l, adopted);
	adopted.push_back(l);
	return chosen;
}

Proposal TableBirthDeath::birthOf(MoveContext& ctx, Id l, Table chosen)
{
	return place(ctx, outcome(ctx, l, chosen, m_candidates));
}

Proposal TableBirthDeath::place(MoveContext& ctx, const Table& chosen)
{
	model::Blackboard& bb = ctx.bb;
	Proposal p{Move::Parent};
	m_invented.clear();

	// Tables the adopted legs leave without any leg that explains a shapelet are pruned at
	// the end of the sweep anyway: the move removes them itself, so it is judged on that.
	m_abandoned.clear();
	for (const Id a : m_candidates)
	{
		const Id parent = bb.leg(a).parent;
		if (parent != NONE && !hasSupportedLeg(bb, parent, m_candidates) &&
			std::find(m_abandoned.begin(), m_abandoned.end(), parent) == m_abandoned.end())
			m_abandoned.push_back(parent);
	}
	// An adopted leg of another width than the table's (an object catalogue's class: a chair's
	// 3 cm legs) is refitted at the table's leg width in the same move; never without a
	// catalogue (every width is then leg_width). When the corner binds a leg tighter than its
	// contacts do (sigma_corner < sigma_r: very noisy readings in the lasting map), every
	// adopted leg is refitted: its best pose under the table is near the corner.
	m_resized.clear();
	const bool refitAll = ctx.mp.cornersTighterThanReadings();
	for (const Id a : m_candidates)
		if (refitAll || bb.leg(a).wx != chosen.leg_width || bb.leg(a).wy != chosen.leg_width) m_resized.push_back(a);
	m_restore = !m_abandoned.empty() || !m_resized.empty();
	if (m_restore) m_backup = bb;

	// Exact change of logJoint, one local step at a time: unlink the adopted legs, resize
	// them (eq. 20 of each before and after), add the table with them all as children (eq. 20
	// of the new table), remove abandoned tables.
	bool reversible = m_abandoned.empty() && m_resized.empty();
	m_oldParents.clear();
	for (const Id a : m_candidates)
	{
		m_oldParents.push_back(bb.leg(a).parent);
		reversible = reversible && bb.leg(a).parent == NONE && bb.explains(a);
		p.logTarget -= model::logLegLinkGain(bb, a, bb.leg(a).parent);
		bb.setLegParent(a, NONE);
	}
	for (const Id a : m_resized)
	{
		model::Leg fit;
		if (!ctx.fittedLeg(a, &chosen, fit)) continue;
		p.logTarget -= model::logOddsLeg(bb, a);
		bb.setLeg(a, fit);
		p.logTarget += model::logOddsLeg(bb, a);
	}
	m_table = bb.addTable(chosen);
	for (const Id a : m_candidates) bb.setLegParent(a, m_table);
	p.logTarget += model::logOddsTable(bb, m_table);
	for (const Id t : m_abandoned) p.logTarget += removeTableAndOrphans(bb, t, m_orphans);
	p.logReverse = reversible ? 0 : -std::numeric_limits<double>::infinity();
	return p;
}

void TableBirthDeath::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	if (m_restore)
	{
		ctx.bb = m_backup;
		return;
	}
	for (const Id l : m_invented) ctx.bb.removeLeg(l);
	ctx.bb.removeTable(m_table);
	for (size_t i = 0; i < m_candidates.size(); i++) ctx.bb.setLegParent(m_candidates[i], m_oldParents[i]);
}

bool TableBirthDeath::hasSupportedLeg(const model::Blackboard& bb, Id table, const std::vector<Id>& except)
{
	for (const Id l : bb.legsOf(table))
		if (bb.explains(l) && std::find(except.begin(), except.end(), l) == except.end()) return true;
	return false;
}
}  // namespace whiskermap::inference::moves
