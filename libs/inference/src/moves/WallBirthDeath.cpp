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

std::optional<Proposal> WallBirthDeath::birth(MoveContext& ctx, size_t seed)
{
	model::Blackboard& bb = ctx.bb;
	const std::optional<WallCandidate> c = proposeWall(bb, seed);
	if (!c) return std::nullopt;
	m_backup = bb;
	const double before = model::logJoint(bb);
	bool wasFree = true;
	std::vector<Id> left;
	const Id w = bb.addWall(c->wall);
	for (const Id s : c->inliers)
	{
		const auto i = static_cast<size_t>(s);
		wasFree = wasFree && !bb.explained(i);
		if (bb.shapeletParent(i) != NONE) left.push_back(bb.shapeletParent(i));
		bb.setShapeletWall(i, w);
	}
	for (const Id l : left)  // free legs left explaining nothing go with the move
		if (bb.hasLeg(l) && !bb.explains(l) && bb.leg(l).parent == NONE) bb.removeLeg(l);
	Proposal p{Move::Parent, model::logJoint(bb) - before};
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
	const double before = model::logJoint(bb);
	bb.removeWall(w);
	Proposal p{Move::Death, model::logJoint(bb) - before};
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
