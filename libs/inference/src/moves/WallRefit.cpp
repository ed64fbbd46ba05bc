#include <whiskermap/inference/WallProposals.h>
#include <whiskermap/inference/moves/WallRefit.h>
#include <whiskermap/model/Posterior.h>

#include <limits>

namespace whiskermap::inference::moves
{
std::optional<Proposal> WallRefit::propose(MoveContext& ctx, model::Id w)
{
	model::Wall fitted;
	if (!fitWall(ctx.bb, w, fitted)) return std::nullopt;
	m_wall = w;
	m_old = ctx.bb.wall(w);
	const double before = model::logOddsWall(ctx.bb, w);
	ctx.bb.setWall(w, fitted);
	Proposal p{Move::Refit, model::logOddsWall(ctx.bb, w) - before};
	p.logReverse = m_old.sameAs(fitted) ? 0 : -std::numeric_limits<double>::infinity();
	return p;
}

void WallRefit::finish(MoveContext& ctx, bool accepted)
{
	if (!accepted) ctx.bb.setWall(m_wall, m_old);
}
}  // namespace whiskermap::inference::moves
