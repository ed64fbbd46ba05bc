#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>
#include <vector>

namespace whiskermap::inference::moves
{
/** Merge of two walls on one line (doc/sampler.md, "Walls"): wall `other`, collinear with w
 *  (normals within 3 sigma_theta, either orientation; w's face lines through other's end
 *  points within the parent gate) and touching or overlapping it along the line (a gap of at
 *  most 0.5 m), is removed; its shapelets and folded evidence go to w (mergeEvidence), and w
 *  refits to them all (fitWall). The lasting map folds a wall's contacts at once, so a wall
 *  growing along a room's side is born in pieces; the merge joins them. Deterministic given
 *  (w, other): logForward = 0; its reverse would be a wall split, which is not written:
 *  logReverse = -inf (like the refits). Judged on the change of logJoint (a copy of the board
 *  restores a rejected merge). */
class WallMerge
{
   public:
	explicit WallMerge(const model::ModelParams& p) : m_backup(p) {}

	/** The walls w can merge with, ascending. */
	static void candidates(const model::Blackboard& bb, model::Id w, std::vector<model::Id>& out);
	std::optional<Proposal> merge(MoveContext& ctx, model::Id w, model::Id other);
	void finish(MoveContext& ctx, bool accepted);

   private:
	model::Blackboard m_backup;
};

/** The folded evidence of two walls as one (the moments of b re-anchored at a's anchor and
 *  re-indexed to a's reference normal): the statistics of all their contacts. */
model::WallEvidence mergeEvidence(const model::WallEvidence& a, const model::WallEvidence& b);
}  // namespace whiskermap::inference::moves
