#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <limits>

namespace whiskermap::model
{
namespace
{
constexpr double NO_CAUSE = -std::numeric_limits<double>::infinity();

// log p(L | pa(L)) by eq. 12: explicit parent (eqs. 5-6) or'ed with the null cause (eq. 8).
double logLegDensity(const Blackboard& bb, const Leg& l, Id table)
{
	const ModelParams& p = bb.params();
	const double cause = table == NONE ? NO_CAUSE : logLegGivenTable(l, bb.table(table), p).logDensity;
	return logNoisyOr(cause, logLegNull(p));
}

// log p(S | pa(S)) by eq. 12: explicit parent (eq. 7) or'ed with the null cause (eq. 9).
double logShapeletDensity(const Blackboard& bb, size_t s, Id leg)
{
	const ModelParams& p = bb.params();
	const double cause = leg == NONE ? NO_CAUSE : logShapeletGivenLeg(bb.shapelets()[s], bb.leg(leg), p);
	return logNoisyOr(cause, logShapeletNull(p));
}

int overlappingTables(const Blackboard& bb, Id t)
{
	const ModelParams& p = bb.params();
	const OrientedRect r = tableRect(bb.table(t), p);
	int n = 0;
	bb.forEachTableNear(r.cx, r.cy, std::hypot(p.table_length, p.table_width), [&](Id o) {
		n += o != t && r.overlaps(tableRect(bb.table(o), p));
	});
	return n;
}

int overlappingLegs(const Blackboard& bb, Id l)
{
	const OrientedRect r = legRect(bb.leg(l));
	int n = 0;
	bb.forEachLegNear(r.cx, r.cy, std::hypot(r.hx, r.hy) + bb.maxLegRadius(), [&](Id o) {
		n += o != l && r.overlaps(legRect(bb.leg(o)));
	});
	return n;
}
}  // namespace

double logJoint(const Blackboard& bb)
{
	const ModelParams& p = bb.params();
	double sum = 0;
	int overlaps = 0;
	for (Id t = 0; t < bb.tableIdBound(); t++)
	{
		if (!bb.hasTable(t)) continue;
		sum += logCell(logTablePrior(p), p) + logTableConstraints(bb.cornerCounts(t), p);
		for (Id o = t + 1; o < bb.tableIdBound(); o++)
			overlaps += bb.hasTable(o) && tableRect(bb.table(t), p).overlaps(tableRect(bb.table(o), p));
	}
	for (Id l = 0; l < bb.legIdBound(); l++)
	{
		if (!bb.hasLeg(l)) continue;
		sum += logCell(logLegDensity(bb, bb.leg(l), bb.leg(l).parent), p);
		for (Id o = l + 1; o < bb.legIdBound(); o++)
			overlaps += bb.hasLeg(o) && legRect(bb.leg(l)).overlaps(legRect(bb.leg(o)));
	}
	for (size_t s = 0; s < bb.shapelets().size(); s++)
		sum += logShapeletDensity(bb, s, bb.shapeletParent(s));
	return sum + logOverlap(overlaps, p);
}

double logLegLinkGain(const Blackboard& bb, Id leg, Id table)
{
	if (table == NONE) return 0;
	const ModelParams& p = bb.params();
	const Leg& l = bb.leg(leg);
	CornerCounts counts = bb.cornerCounts(table, leg);
	const double before = logTableConstraints(counts, p);
	counts[logLegGivenTable(l, bb.table(table), p).corner]++;
	return logLegDensity(bb, l, table) - logLegNull(p) + logTableConstraints(counts, p) - before;
}

double logShapeletLinkGain(const Blackboard& bb, size_t s, Id leg)
{
	return leg == NONE ? 0 : logShapeletDensity(bb, s, leg) - logShapeletNull(bb.params());
}

double logOddsTable(const Blackboard& bb, Id table)
{
	const ModelParams& p = bb.params();
	double sum = logCell(logTablePrior(p), p) + logTableConstraints(bb.cornerCounts(table), p) +
				 logOverlap(overlappingTables(bb, table), p);
	for (Id l = 0; l < bb.legIdBound(); l++)
		if (bb.hasLeg(l) && bb.leg(l).parent == table)
			sum += logLegDensity(bb, bb.leg(l), table) - logLegNull(p);
	return sum;
}

double logOddsLeg(const Blackboard& bb, Id leg)
{
	const ModelParams& p = bb.params();
	double sum = logCell(logLegNull(p), p) + logLegLinkGain(bb, leg, bb.leg(leg).parent) +
				 logOverlap(overlappingLegs(bb, leg), p);
	for (size_t s = 0; s < bb.shapelets().size(); s++)
		if (bb.shapeletParent(s) == leg) sum += logShapeletLinkGain(bb, s, leg);
	return sum;
}

double annealedAcceptance(double logOdds, double beta)
{
	return 1 / (1 + std::exp(-beta * logOdds));  // eq. 20, annealed
}
}  // namespace whiskermap::model
