#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>
#include <vector>

namespace whiskermap::inference::moves
{
/** Links between shapelets and a wall (doc/sampler.md, "Walls"), each the other's reverse,
 *  without refit (WallRefit moves the wall):
 *  - link(w): a shapelet near w's faces (within the parent gate of a face segment, its normal
 *    within 3 sigma_theta of that face's, not on w) drawn uniformly among those candidates
 *    moves to w from its leg, other wall or nothing. logForward = -log(candidates); reverse:
 *    release of it, -log(w's shapelets after) when it had no cause before, else -inf;
 *  - release(w): one of w's shapelets, drawn uniformly, is left without a cause (priming then
 *    offers it a leg). logForward = -log(w's shapelets); reverse: link, -log(candidates after).
 *  Judged on the change of the shapelet's density (eq. 12 with eq. 22, 7 or 9): exact, as no
 *  other term depends on which shapelets a hypothesis explains. */
class WallLink
{
   public:
	std::optional<Proposal> link(MoveContext& ctx, model::Id w);
	std::optional<Proposal> release(MoveContext& ctx, model::Id w);
	/** Candidates of link(w) (shapelet indices, ascending). */
	static void candidates(const model::Blackboard& bb, model::Id w, std::vector<model::Id>& out);
	void finish(MoveContext& ctx, bool accepted);
	/** The greedy polish: offers link() for every candidate in turn. */
	void polish(MoveContext& ctx, model::Id w);

   private:
	std::optional<Proposal> linkShapelet(MoveContext& ctx, model::Id w, size_t s, size_t candidates);
	size_t m_shapelet = 0;
	model::Id m_fromLeg = model::NONE, m_fromWall = model::NONE;
	std::vector<model::Id> m_candidates;
};
}  // namespace whiskermap::inference::moves
