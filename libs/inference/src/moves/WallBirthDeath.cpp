#include <whiskermap/inference/WallProposals.h>
#include <whiskermap/inference/moves/WallBirthDeath.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <limits>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

namespace
{
constexpr double NO_REVERSE = -std::numeric_limits<double>::infinity();
}  // namespace

// The change of logJoint from its local pieces, one step at a time (each exact for its step):
// the inliers unlinked from their legs or walls (eq. 12: their own terms only), the free legs
// left explaining nothing removed (eq. 20: logOddsLeg), the wall added with the inliers
// (eq. 20: logOddsWall). Tested against logJoint differences (WallMoves_unittest.cpp).
std::optional<Proposal> WallBirthDeath::birth(MoveContext& ctx, size_t seed)
{
	model::Blackboard& bb = ctx.bb;
	const std::optional<WallCandidate> c = proposeWall(bb, seed);
	if (!c) return std::nullopt;
	m_backup = bb;
	double change = 0;
	bool wasFree = true;
	m_left.clear();
	for (const Id s : c->inliers)
	{
		const auto i = static_cast<size_t>(s);
		wasFree = wasFree && !bb.explained(i);
		if (bb.shapeletParent(i) != NONE) m_left.push_back(bb.shapeletParent(i));
		change -= model::logShapeletLinked(bb, i);
		bb.setShapeletParent(i, NONE);
		bb.setShapeletWall(i, NONE);
		change += model::logShapeletLinked(bb, i);
	}
	for (const Id l : m_left)  // free legs left explaining nothing go with the move
		if (bb.hasLeg(l) && !bb.explains(l) && bb.leg(l).parent == NONE)
		{
			change -= model::logOddsLeg(bb, l);
			bb.removeLeg(l);
		}
	const Id w = bb.addWall(c->wall);
	for (const Id s : c->inliers) bb.setShapeletWall(static_cast<size_t>(s), w);
	change += model::logOddsWall(bb, w);
	Proposal p{Move::Parent, change};
	p.logReverse = wasFree ? 0 : NO_REVERSE;
	return p;
}

std::optional<Proposal> WallBirthDeath::death(MoveContext& ctx, Id w)
{
	model::Blackboard& bb = ctx.bb;
	if (!bb.wallEvidence(w).empty()) return std::nullopt;
	m_backup = bb;
	const model::Wall wall = bb.wall(w);
	const std::vector<Id> shapelets = bb.shapeletsOfWall(w);
	Proposal p{Move::Death, -model::logOddsWall(bb, w)};  // eq. 20: its shapelets fall to the null cause
	bb.removeWall(w);
	p.logReverse = NO_REVERSE;
	for (const Id s : shapelets)
	{
		const std::optional<WallCandidate> c = proposeWall(bb, static_cast<size_t>(s));
		if (c && c->inliers == shapelets && c->wall.sameAs(wall))
		{
			p.logReverse = 0;
			break;
		}
	}
	return p;
}

void WallBirthDeath::finish(MoveContext& ctx, bool accepted)
{
	if (!accepted) ctx.bb = m_backup;
}
}  // namespace whiskermap::inference::moves
