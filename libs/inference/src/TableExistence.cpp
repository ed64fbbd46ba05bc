#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/TableExistence.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/TableProposals.h>
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

namespace
{
/** Two tables are the same hypothesis when they have the same class and their centres agree
 *  within a quarter of the class's width and their yaws (mod 180 deg; mod 90 deg for a square class) within 15 degrees: distinct hypotheses on the
 *  same legs (mirror images, other corners) are at least half a width or 60 degrees apart. */
bool same(const Table& a, const Table& b, const model::ModelParams& p)
{
	// a square class (a chair) is the same object turned by 90 degrees: yaw modulo 90 degrees
	const double period = p.lengthOf(a.cls) == p.widthOf(a.cls) ? M_PI_2 : M_PI;
	return a.cls == b.cls && std::hypot(a.x - b.x, a.y - b.y) <= p.widthOf(a.cls) / 4 &&
		   std::abs(core::angleDiff(a.theta, b.theta, period)) <= core::deg2rad(15);
}
}  // namespace

std::vector<double> TableExistence::of(const model::Blackboard& bb)
{
	std::vector<double> out(static_cast<size_t>(bb.tableIdBound()), 0.0);
	for (Id t = 0; t < bb.tableIdBound(); t++)
		if (bb.hasTable(t)) out[static_cast<size_t>(t)] = of(bb, t);
	return out;
}

double TableExistence::of(const model::Blackboard& bb, Id t)
{
	const model::ModelParams& p = bb.params();
	m_without = bb;  // reuses the scratch board's storage
	const double sT = -removeTableAndOrphans(m_without, t, m_orphans);
	// Rivals: pair tables through the legs of t that explain contacts, each scored on the
	// board without t and then taken off it again.
	double rivals = 0;  // sum of exp(s_R - s_T)
	m_scored.assign(1, bb.table(t));
	const auto scored = [&](const Table& r) {
		return std::any_of(m_scored.begin(), m_scored.end(), [&](const Table& s) { return same(s, r, p); });
	};
	for (const Id l : bb.legsOf(t))
	{
		if (!bb.explains(l)) continue;
		m_rivals.clear();
		tablesForPairs(m_without, l, m_rivals);
		for (const Table& r : m_rivals)
		{
			// A rival that cannot come within 20 nats of t (its best case with l and the legs
			// it adopts) changes P(t) by less than 2e-9: not scored.
			if (bound(p, adoptable(m_without, r, l, m_adopted) + 1) < sT - 20) continue;
			// Pair tables fitted to two legs settle within millimetres: one already scored
			// (or t itself) is not scored again (each pair of legs proposes its tables twice).
			if (scored(r)) continue;
			// The rival as it settles on the legs it adopts; counted once, and never when it
			// settles on t itself.
			Table settled = r;
			const double sR = scoreRival(m_without, settled, l);
			if (scored(settled)) continue;
			m_scored.push_back(settled);
			rivals += std::exp(std::min(sR - sT, 700.0));
		}
	}
	return 1 / (1 + std::exp(std::min(-sT, 700.0)) + rivals);
}

double TableExistence::bound(const model::ModelParams& p, size_t legs)
{
	// eq. 20 of a table with `legs` legs each at its corner exactly (eqs. 5-6, 8), and the
	// best of a missing leg (eq. 15) or an invented one at each other corner.
	const double k = static_cast<double>(std::min<size_t>(legs, 4));
	const double linked = core::cachedLog(p.alpha_L + p.c_L) - model::logLegNull(p);
	const double other = std::max(core::cachedLog(p.epsilon), model::logCell(core::cachedLog(p.alpha_L + p.c_L), p));
	return model::logCell(model::logTablePrior(p), p) + k * linked + (4 - k) * other;
}

double TableExistence::scoreRival(model::Blackboard& bb, Table& t, Id leg)
{
	const model::ModelParams& p = bb.params();
	// Adopt the free legs the table reaches (with `leg`), fit the table to them, adopt anew.
	for (int round = 0; round < 2; round++)
	{
		adoptable(bb, t, leg, m_adopted);
		m_adopted.erase(
			std::remove_if(m_adopted.begin(), m_adopted.end(), [&](Id a) { return bb.leg(a).parent != NONE; }),
			m_adopted.end());
		m_adopted.push_back(leg);
		if (round == 1) break;
		m_fitLegs.clear();
		m_fitCorners.clear();
		for (const Id a : m_adopted)
		{
			m_fitLegs.push_back(&bb.leg(a));
			m_fitCorners.push_back(model::logLegGivenTable(bb.leg(a), t, p).corner);
		}
		t = fitTable(p, t, m_fitLegs.data(), m_fitCorners.data(), m_fitLegs.size());
	}
	const Id id = bb.addTable(t);
	for (const Id a : m_adopted) bb.setLegParent(a, id);
	double s = model::logOddsTable(bb, id);
	// Invented legs at the empty corners, where they pay (eq. 20 of each).
	const model::CornerCounts counts = bb.cornerCounts(id);
	m_invented.clear();
	for (int c = 0; c < 4; c++)
	{
		if (counts[c] > 0) continue;
		const Id li = bb.addLeg(moves::LegBirthDeath::atCorner(p, t, c, id));
		const double gain = model::logOddsLeg(bb, li);
		if (gain > 0)
			s += gain, m_invented.push_back(li);
		else
			bb.removeLeg(li);
	}
	// Off the board again, last in first out (the adopted legs fall back to no parent).
	for (auto it = m_invented.rbegin(); it != m_invented.rend(); ++it) bb.removeLeg(*it);
	bb.removeTable(id);
	return s;
}
}  // namespace whiskermap::inference
