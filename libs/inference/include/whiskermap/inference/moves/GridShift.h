#pragma once
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/inference/moves/PoseGrid.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** A table or a leg moves to another pose of the grid, for the random scan (doc/sampler.md,
 *  "Random scan on a pose grid"): a table (leg) uniformly, then one of the other grid poses
 *  uniformly; links stay (corners re-derived). Each is its own exact reverse: logForward =
 *  logReverse = -log(tables) - log(|T| - 1) (legs: -log(legs) - log(|G| - 1)). Not
 *  proposed when the hypothesis is off the grid or a linked leg would end beyond the parent
 *  gate of its corner (LegReparent::withinGate: a leg is only ever linked within it).
 *  logTarget: the change of logJointAround (table) or of eq. 20 (leg). */
class GridShift
{
   public:
	explicit GridShift(const PoseGrid& grid) : m_grid(grid) {}

	std::optional<Proposal> table(MoveContext& ctx);
	std::optional<Proposal> leg(MoveContext& ctx);
	void finish(MoveContext& ctx, bool accepted);

   private:
	const PoseGrid& m_grid;
	bool m_isTable = false;
	model::Id m_id = model::NONE;
	model::Table m_oldTable;
	model::Leg m_oldLeg;
};
}  // namespace whiskermap::inference::moves
