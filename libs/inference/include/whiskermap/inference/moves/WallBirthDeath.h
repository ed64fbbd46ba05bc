#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <vector>

namespace whiskermap::inference::moves
{
/** Birth and death of a wall (doc/sampler.md, "Walls"), each the other's reverse:
 *  - birth(s): the data-driven wall seeded at shapelet s (proposeWall: its face line, the
 *    run of agreeing contacts along it, the closed-form fit); the inliers leave their legs
 *    or nothing for it, and free legs left explaining nothing are removed in the same move.
 *    Deterministic given s: logForward = 0. Reverse: death of the new wall, logReverse = 0
 *    when every inlier was unexplained before (the death then restores the board), else -inf;
 *  - death(w) (not for walls holding folded contacts): w removed, its shapelets unexplained.
 *    logForward = 0; reverse: the birth seeded at one of its shapelets, logReverse = 0 when
 *    one of them proposes exactly w with exactly its shapelets, else -inf.
 *  Judged on the exact change of logJoint (the board's, before and after); undone by restoring
 *  a copy of the board. */
class WallBirthDeath
{
   public:
	explicit WallBirthDeath(const model::ModelParams& p) : m_backup(p) {}

	std::optional<Proposal> birth(MoveContext& ctx, size_t seed);
	std::optional<Proposal> death(MoveContext& ctx, model::Id w);
	void finish(MoveContext& ctx, bool accepted);

   private:
	model::Blackboard m_backup;
	std::vector<model::Id> m_left;  ///< legs the inliers leave (scratch)
};
}  // namespace whiskermap::inference::moves
