#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/moves/WallLink.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

namespace
{
constexpr double NO_REVERSE = -std::numeric_limits<double>::infinity();

/** True if shapelet s lies within the gate of a face segment of w with an agreeing normal. */
bool nearFace(const model::Blackboard& bb, Id w, size_t s)
{
	const model::ModelParams& p = bb.params();
	const obs::Shapelet& sh = bb.shapelets()[s];
	const model::Wall& wall = bb.wall(w);
	if (wall.farFrom(sh.x, sh.y, p.parent_gate)) return false;  // within the gate of a face is within it of the slab
	const model::Wall::Frame& fr = bb.wallFrame(w);
	const int side = model::bestWallFace(sh, wall, fr, p);
	const model::Wall::FaceHit h = wall.hit(fr, sh.x, sh.y, side);
	return std::hypot(h.across, h.excess) <= p.parent_gate &&
		   std::abs(core::wrapToPi(sh.normal - h.normal)) <= 3 * p.sigma_theta;
}
}  // namespace

void WallLink::candidates(const model::Blackboard& bb, Id w, std::vector<Id>& out)
{
	out.clear();
	for (size_t s = 0; s < bb.shapelets().size(); s++)
		if (bb.shapeletWall(s) != w && nearFace(bb, w, s)) out.push_back(static_cast<Id>(s));
}

std::optional<Proposal> WallLink::linkShapelet(MoveContext& ctx, Id w, size_t s, size_t n)
{
	model::Blackboard& bb = ctx.bb;
	m_shapelet = s;
	m_fromLeg = bb.shapeletParent(s), m_fromWall = bb.shapeletWall(s);
	const double before = model::logShapeletLinked(bb, s);
	bb.setShapeletWall(s, w);
	Proposal p{Move::Child, model::logShapeletLinked(bb, s) - before};
	p.logForward = -std::log(static_cast<double>(n));
	p.logReverse = m_fromLeg == NONE && m_fromWall == NONE ? -std::log(static_cast<double>(bb.shapeletsOfWall(w).size()))
														  : NO_REVERSE;
	return p;
}

std::optional<Proposal> WallLink::link(MoveContext& ctx, Id w)
{
	candidates(ctx.bb, w, m_candidates);
	if (m_candidates.empty()) return std::nullopt;
	const auto s = static_cast<size_t>(m_candidates[ctx.rng.pick(m_candidates.size())]);
	return linkShapelet(ctx, w, s, m_candidates.size());
}

std::optional<Proposal> WallLink::release(MoveContext& ctx, Id w)
{
	model::Blackboard& bb = ctx.bb;
	const std::vector<Id>& own = bb.shapeletsOfWall(w);
	if (own.empty()) return std::nullopt;
	const size_t n = own.size();
	const auto s = static_cast<size_t>(own[ctx.rng.pick(n)]);
	m_shapelet = s, m_fromLeg = NONE, m_fromWall = w;
	const double before = model::logShapeletLinked(bb, s);
	bb.setShapeletWall(s, NONE);
	Proposal p{Move::Child, model::logShapeletLinked(bb, s) - before};
	p.logForward = -std::log(static_cast<double>(n));
	candidates(bb, w, m_candidates);
	p.logReverse = nearFace(bb, w, s) ? -std::log(static_cast<double>(m_candidates.size())) : NO_REVERSE;
	return p;
}

void WallLink::finish(MoveContext& ctx, bool accepted)
{
	if (accepted) return;
	model::Blackboard& bb = ctx.bb;
	if (m_fromWall != NONE) bb.setShapeletWall(m_shapelet, m_fromWall);
	else if (m_fromLeg != NONE) bb.setShapeletParent(m_shapelet, m_fromLeg);
	else bb.setShapeletWall(m_shapelet, NONE);
}

void WallLink::polish(MoveContext& ctx, Id w)
{
	std::vector<Id> all;
	candidates(ctx.bb, w, all);
	for (const Id s : all)
		if (ctx.bb.hasWall(w) && ctx.bb.shapeletWall(static_cast<size_t>(s)) != w)
			if (const auto p = linkShapelet(ctx, w, static_cast<size_t>(s), all.size())) ctx.judge(*this, *p);
}
}  // namespace whiskermap::inference::moves
