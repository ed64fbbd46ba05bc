#pragma once
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/inference/moves/PoseGrid.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Births and deaths on a PoseGrid for the random scan (doc/sampler.md, "Random scan on a
 *  pose grid"), each drawing its own target, with exact densities both ways:
 *  - legBirth: a shapelet s uniformly among all N; if s has no leg, a new free leg for it at
 *    a grid pose drawn uniformly: logForward = -log N - log |G|; reverse legDeath picks that
 *    leg among the legs after: logReverse = -log(legs after);
 *  - legDeath: a leg uniformly among the legs; proposed only for a free leg holding exactly
 *    one shapelet, no folded evidence, at a grid pose: logForward = -log(legs), logReverse =
 *    -log N - log |G|;
 *  - tableBirth: while fewer than maxTables, a table at a grid pose drawn uniformly; it
 *    adopts every free leg within the parent gate of a corner (LegReparent::withinGate), a
 *    deterministic choice: logForward = -log |T|, logReverse = -log(tables after);
 *  - tableDeath: a table uniformly; removed, its legs left free (poses unchanged); proposed
 *    only when it is at a grid pose and no free leg is within its gate (so that the birth at
 *    its pose adopts exactly its legs): logForward = -log(tables), logReverse = -log |T|.
 *  logTarget is eq. 20 of the hypothesis born or removed. */
class GridBirthDeath
{
   public:
	explicit GridBirthDeath(const PoseGrid& grid) : m_grid(grid) {}

	std::optional<Proposal> legBirth(MoveContext& ctx);
	std::optional<Proposal> legDeath(MoveContext& ctx);
	std::optional<Proposal> tableBirth(MoveContext& ctx);
	std::optional<Proposal> tableDeath(MoveContext& ctx);
	void finish(MoveContext& ctx, bool accepted);

   private:
	const PoseGrid& m_grid;
	bool m_birth = false, m_table = false;
	model::Id m_id = model::NONE;
};
}  // namespace whiskermap::inference::moves
