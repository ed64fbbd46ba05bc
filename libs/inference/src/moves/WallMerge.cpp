#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/WallProposals.h>
#include <whiskermap/inference/moves/WallMerge.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::WallEvidence;

namespace
{
constexpr double WALL_GAP = 0.5;  ///< as proposeWall's run: the largest gap along one wall

/** Signed distance of point (x, y) from wall w's centre line (positive on face +1's side). */
double offset(const model::Wall& w, double x, double y) { return w.face(x, y, 1).across + w.thickness / 2; }
}  // namespace

WallEvidence mergeEvidence(const WallEvidence& a, const WallEvidence& b)
{
	if (a.empty()) return b;
	if (b.empty()) return a;
	// Layout of stats(): ax, ay, phi, face 0 (w, sx, sy, sxx, sxy, syy), face 1 (the same),
	// wa, sa, saa, wt, st, stt, lox, loy, hix, hiy, the end caps' frozen cost.
	auto s = a.stats();
	const auto t = b.stats();
	const double dx = t[0] - s[0], dy = t[1] - s[1];  // b's anchor from a's
	const bool flip = std::cos(t[2] - s[2]) < 0;  // b's reference face is a's face 1
	for (int k = 0; k < 2; k++)
	{
		const size_t from = 3 + 6 * static_cast<size_t>(k), to = 3 + 6 * static_cast<size_t>(flip ? 1 - k : k);
		const double w = t[from], sx = t[from + 1], sy = t[from + 2];
		s[to] += w;
		s[to + 1] += sx + w * dx;
		s[to + 2] += sy + w * dy;
		s[to + 3] += t[from + 3] + 2 * dx * sx + w * dx * dx;
		s[to + 4] += t[from + 4] + dx * sy + dy * sx + w * dx * dy;
		s[to + 5] += t[from + 5] + 2 * dy * sy + w * dy * dy;
	}
	// Normal errors: b's are against phi_b (+ pi on its face 1); against a's reference they
	// are larger by d, the turn from a's reference face normal to b's matching one.
	const double d = core::wrapToPi(t[2] - s[2] - (flip ? M_PI : 0));
	const double wa = t[15], sa = t[16], saa = t[17];
	s[15] += wa, s[16] += sa + wa * d, s[17] += saa + 2 * d * sa + wa * d * d;
	s[18] += t[18], s[19] += t[19], s[20] += t[20];
	s[25] += t[25];
	// Extent along a's reference direction: the furthest of the four end contacts.
	const double ux = std::sin(s[2]), uy = -std::cos(s[2]);
	const auto along = [&](double x, double y) { return ux * (x - s[0]) + uy * (y - s[1]); };
	for (const size_t i : {21u, 23u})
	{
		if (along(t[i], t[i + 1]) < along(s[21], s[22])) s[21] = t[i], s[22] = t[i + 1];
		if (along(t[i], t[i + 1]) > along(s[23], s[24])) s[23] = t[i], s[24] = t[i + 1];
	}
	return WallEvidence::fromStats(s, a.count() + b.count());
}

void WallMerge::candidates(const model::Blackboard& bb, Id w, std::vector<Id>& out)
{
	out.clear();
	const model::ModelParams& p = bb.params();
	const model::Wall& a = bb.wall(w);
	const double len = a.length();
	for (Id v = 0; v < bb.wallIdBound(); v++)
	{
		if (v == w || !bb.hasWall(v)) continue;
		const model::Wall& b = bb.wall(v);
		// Collinear: the faces parallel (either orientation) and b's centre line on a's.
		const double turn = std::atan2(b.y1 - b.y0, b.x1 - b.x0) - std::atan2(a.y1 - a.y0, a.x1 - a.x0);
		if (std::abs(core::angleDiff(turn, 0, M_PI)) > 3 * p.sigma_theta) continue;
		if (std::abs(offset(a, b.x0, b.y0)) > p.parent_gate || std::abs(offset(a, b.x1, b.y1)) > p.parent_gate) continue;
		// Touching along the line: b's extent within WALL_GAP of a's.
		const double u0 = a.face(b.x0, b.y0, 1).along, u1 = a.face(b.x1, b.y1, 1).along;
		if (std::max(u0, u1) < -WALL_GAP || std::min(u0, u1) > len + WALL_GAP) continue;
		out.push_back(v);
	}
}

std::optional<Proposal> WallMerge::merge(MoveContext& ctx, Id w, Id other)
{
	model::Blackboard& bb = ctx.bb;
	m_backup = bb;
	// The change of logJoint from local pieces (eq. 20), one step at a time: both walls removed
	// (their shapelets to the null cause), the merged wall added with them all.
	const WallEvidence merged = mergeEvidence(bb.wallEvidence(w), bb.wallEvidence(other));
	const std::vector<Id> moved = bb.shapeletsOfWall(other);
	const model::Wall keep = bb.wall(w);
	double change = -model::logOddsWall(bb, other);
	bb.removeWall(other);
	change -= model::logOddsWall(bb, w);
	bb.removeWall(w);
	const Id id = bb.addWall(keep, merged);  // the same slot: removed last, reused first
	for (const Id s : moved) bb.setShapeletWall(static_cast<size_t>(s), id);
	for (const Id s : m_backup.shapeletsOfWall(w)) bb.setShapeletWall(static_cast<size_t>(s), id);
	model::Wall fitted;
	if (fitWall(bb, id, fitted)) bb.setWall(id, fitted);
	Proposal p{Move::Refit, change + model::logOddsWall(bb, id)};
	p.logReverse = -std::numeric_limits<double>::infinity();
	return p;
}

void WallMerge::finish(MoveContext& ctx, bool accepted)
{
	if (!accepted) ctx.bb = m_backup;
}
}  // namespace whiskermap::inference::moves
