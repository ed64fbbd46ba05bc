#include <whiskermap/model/Densities.h>
#include <whiskermap/model/GridFreeSpace.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
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

// The walls whose slab shares interior points with rectangle r (eq. 16 between a leg and a wall).
int overlappingWalls(const Blackboard& bb, const OrientedRect& r)
{
	int n = 0;
	const double reach = std::hypot(r.hx, r.hy);  // r lies within this of its centre
	for (Id w = 0; w < bb.wallIdBound(); w++)
		n += bb.hasWall(w) && !bb.wall(w).farFrom(r.cx, r.cy, reach) && r.overlaps(bb.wall(w).rect());
	return n;
}

// Same-type overlaps of table t (leg l) with the board's other hypotheses and, separately,
// with the context objects (eq. 16).
struct Overlaps
{
	int board = 0, context = 0;
};

Overlaps overlappingTables(const Blackboard& bb, Id t)
{
	const ModelParams& p = bb.params();
	const OrientedRect r = tableRect(bb.table(t), p);
	const double reach = p.maxDiagonal();
	Overlaps n;
	bb.forEachTableNear(r.cx, r.cy, reach, [&](Id o) { n.board += o != t && r.overlaps(tableRect(bb.table(o), p)); });
	bb.forEachContextTableNear(r.cx, r.cy, reach, [&](Id o) {
		n.context += r.overlaps(tableRect(bb.contextTables()[static_cast<size_t>(o)], p));
	});
	return n;
}

Overlaps overlappingLegs(const Blackboard& bb, Id l)
{
	const OrientedRect r = legRect(bb.leg(l));
	const double reach = std::hypot(r.hx, r.hy) + bb.maxLegRadius();
	Overlaps n;
	bb.forEachLegNear(r.cx, r.cy, reach, [&](Id o) { n.board += o != l && r.overlaps(legRect(bb.leg(o))); });
	bb.forEachContextLegNear(r.cx, r.cy, reach, [&](Id o) {
		n.context += r.overlaps(legRect(bb.contextLegs()[static_cast<size_t>(o)]));
	});
	n.context += overlappingWalls(bb, r);  // a leg standing in a wall: counted once, from the leg
	return n;
}

// The factors a table owns given its children: phi_a, phi_b (eqs. 15, 17) and the free space
// at its empty corners (eq. 21; in the lasting map, the swept grid's: eq. 27).
double tableFactors(const Blackboard& bb, Id t, const CornerCounts& counts)
{
	const ModelParams& p = bb.params();
	double sum = logTableConstraints(counts, p) + bb.swept().logEmptyCorners(bb.table(t), counts, p);
	if (p.free_space && bb.sweptGrid()) sum += GridFreeSpace::logEmptyCorners(bb.table(t), counts, *bb.sweptGrid(), p);
	return sum;
}

// The free space a leg reaches into (eq. 21; in the lasting map, the swept grid's: eq. 27).
double freeSpace(const Blackboard& bb, Id l)
{
	const ModelParams& p = bb.params();
	const Leg& leg = bb.leg(l);
	double sum = bb.swept().logFactor(legRect(leg), p);
	if (p.free_space && bb.sweptGrid()) sum += GridFreeSpace::logLegFactor(leg.x, leg.y, leg.wx, *bb.sweptGrid(), p);
	return sum;
}

// The folded contacts of a leg against their null cause: log p(S | L) - log c_S summed
// (eqs. 7, 9, 12).
double evidenceGain(const Blackboard& bb, Id l)
{
	const LegEvidence& e = bb.evidence(l);
	return e.empty() ? 0 : e.logLikelihood(bb.leg(l), bb.params()) - e.count() * logShapeletNull(bb.params());
}
// The folded contacts of a wall against their null cause (eqs. 22, 9, 12), as evidenceGain.
double wallEvidenceGain(const Blackboard& bb, Id w)
{
	const WallEvidence& e = bb.wallEvidence(w);
	return e.empty() ? 0 : e.logLikelihood(bb.wall(w), bb.wallFrame(w), bb.params()) - e.count() * logShapeletNull(bb.params());
}

// A wall's own factors: its cell (eq. 23), its folded contacts, and with free space on the
// lasting map's swept grid (eq. 25).
double wallOwnFactors(const Blackboard& bb, Id w)
{
	const ModelParams& p = bb.params();
	const Wall& wall = bb.wall(w);
	double sum = logWallPrior(wall, p) + wallEvidenceGain(bb, w) + bb.swept().logWallFactor(wall, p);  // eq. 21
	if (p.free_space && bb.sweptGrid()) sum += GridFreeSpace::logWallFactor(wall, *bb.sweptGrid(), p);
	return sum;
}
}  // namespace

// log p(S | pa(S)) of shapelet s as the board links it: its leg (eq. 7) or its wall (eq. 22),
// or'ed with the null cause (eqs. 9, 12).
double logShapeletLinked(const Blackboard& bb, size_t s)
{
	const Id w = bb.shapeletWall(s);
	if (w == NONE) return logShapeletDensity(bb, s, bb.shapeletParent(s));
	const ModelParams& p = bb.params();
	return logNoisyOr(logShapeletGivenWall(bb.shapelets()[s], bb.wall(w), bb.wallFrame(w), p), logShapeletNull(p));
}

double logJoint(const Blackboard& bb)
{
	const ModelParams& p = bb.params();
	double sum = 0;
	int boardPairs = 0, contextPairs = 0;  // board pairs are seen from both sides
	for (Id t = 0; t < bb.tableIdBound(); t++)
	{
		if (!bb.hasTable(t)) continue;
		sum += logCell(logTablePrior(bb.table(t), p), p) + tableFactors(bb, t, bb.cornerCounts(t));
		const Overlaps o = overlappingTables(bb, t);
		boardPairs += o.board, contextPairs += o.context;
	}
	for (Id l = 0; l < bb.legIdBound(); l++)
	{
		if (!bb.hasLeg(l)) continue;
		sum += logCell(logLegDensity(bb, bb.leg(l), bb.leg(l).parent), p);
		sum += evidenceGain(bb, l);  // folded contacts, relative to their null cause
		sum += freeSpace(bb, l);
		const Overlaps o = overlappingLegs(bb, l);
		boardPairs += o.board, contextPairs += o.context;
	}
	for (Id w = 0; w < bb.wallIdBound(); w++)
		if (bb.hasWall(w)) sum += wallOwnFactors(bb, w);  // eqs. 21, 23, 25
	for (size_t s = 0; s < bb.shapelets().size(); s++) sum += logShapeletLinked(bb, s);
	return sum + logOverlap(boardPairs / 2 + contextPairs, p);
}

double logJointAround(const Blackboard& bb, Id table)
{
	const ModelParams& p = bb.params();
	const std::vector<Id>& legs = bb.legsOf(table);
	const Overlaps to = overlappingTables(bb, table);
	double sum = logCell(logTablePrior(bb.table(table), p), p) + tableFactors(bb, table, bb.cornerCounts(table));
	int pairs = to.board + to.context;
	for (const Id l : legs)
	{
		sum += logCell(logLegDensity(bb, bb.leg(l), table), p) + evidenceGain(bb, l) + freeSpace(bb, l);
		for (const Id s : bb.shapeletsOf(l)) sum += logShapeletDensity(bb, static_cast<size_t>(s), l);
		// Overlaps with legs outside the group, and inside it once per pair.
		const OrientedRect r = legRect(bb.leg(l));
		bb.forEachLegNear(r.cx, r.cy, std::hypot(r.hx, r.hy) + bb.maxLegRadius(), [&](Id o) {
			const bool inside = std::find(legs.begin(), legs.end(), o) != legs.end();
			if (o != l && (!inside || o > l)) pairs += r.overlaps(legRect(bb.leg(o)));
		});
		bb.forEachContextLegNear(r.cx, r.cy, std::hypot(r.hx, r.hy) + bb.maxLegRadius(), [&](Id o) {
			pairs += r.overlaps(legRect(bb.contextLegs()[static_cast<size_t>(o)]));
		});
		pairs += overlappingWalls(bb, r);
	}
	return sum + logOverlap(pairs, p);
}

double logLegLinkGain(const Blackboard& bb, Id leg, Id table)
{
	if (table == NONE) return 0;
	const ModelParams& p = bb.params();
	const Leg& l = bb.leg(leg);
	CornerCounts counts = bb.cornerCounts(table, leg);
	const double before = tableFactors(bb, table, counts);
	counts[logLegGivenTable(l, bb.table(table), p).corner]++;
	return logLegDensity(bb, l, table) - logLegNull(p) + tableFactors(bb, table, counts) - before;
}

double logShapeletLinkGain(const Blackboard& bb, size_t s, Id leg)
{
	return leg == NONE ? 0 : logShapeletDensity(bb, s, leg) - logShapeletNull(bb.params());
}

double logOddsTable(const Blackboard& bb, Id table)
{
	const ModelParams& p = bb.params();
	const Overlaps o = overlappingTables(bb, table);
	double sum = logCell(logTablePrior(bb.table(table), p), p) + tableFactors(bb, table, bb.cornerCounts(table)) +
				 logOverlap(o.board + o.context, p);
	for (const Id l : bb.legsOf(table)) sum += logLegDensity(bb, bb.leg(l), table) - logLegNull(p);
	return sum;
}

double logOddsLeg(const Blackboard& bb, Id leg)
{
	const ModelParams& p = bb.params();
	const Overlaps o = overlappingLegs(bb, leg);
	double sum = logCell(logLegNull(p), p) + logLegLinkGain(bb, leg, bb.leg(leg).parent) +
				 logOverlap(o.board + o.context, p) + evidenceGain(bb, leg) + freeSpace(bb, leg);
	for (const Id s : bb.shapeletsOf(leg)) sum += logShapeletLinkGain(bb, static_cast<size_t>(s), leg);
	return sum;
}

double logOddsWall(const Blackboard& bb, Id wall)
{
	const ModelParams& p = bb.params();
	const Wall& w = bb.wall(wall);
	double sum = wallOwnFactors(bb, wall);  // eqs. 23, 25
	for (const Id s : bb.shapeletsOfWall(wall)) sum += logShapeletLinked(bb, static_cast<size_t>(s)) - logShapeletNull(p);
	int legs = 0;
	const OrientedRect r = w.rect();
	for (Id l = 0; l < bb.legIdBound(); l++)  // a leg lies within maxLegRadius of its centre
		legs += bb.hasLeg(l) && !w.farFrom(bb.leg(l).x, bb.leg(l).y, bb.maxLegRadius()) && legRect(bb.leg(l)).overlaps(r);
	return sum + logOverlap(legs, p);
}

double annealedAcceptance(double logOdds, double beta)
{
	return 1 / (1 + std::exp(-beta * logOdds));  // eq. 20, annealed
}
}  // namespace whiskermap::model
