#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>
#include <utility>
#include <vector>

namespace whiskermap::inference::moves
{
/** Refit of a table's leg width and leg texture (eq. 26, doc/sampler.md "Moves"; registered
 *  with `size_moves` when a class of the catalogue has a leg_width_sigma or texture_sigma > 0).
 *  Texture: twice, the closed-form optimum of eqs. 6 and 26 given the textures of its legs
 *  that explain shapelets, those legs then refitted (their texture is the mean of the table's
 *  and their contacts'). Leg width: a parabola through the exact logJointAround at the current
 *  width and one step (leg_width_sigma / 2, at most 5 mm) either side, each with the legs
 *  refitted as squares of that width; its vertex (at most two steps away and half the table's
 *  smaller leg spacing, at least 1 mm), else the best of the three. Judged on the exact change
 *  of logJoint. Deterministic (logForward = 0), no reverse (logReverse = -inf) unless nothing
 *  moved (0). Not with broad proposals (an optimiser, like the leg pose search). */
class TableLegFit
{
   public:
	/** nullopt (board unchanged) with broad proposals, for a table of a class whose legs do
	 *  not vary, when no leg of t explains a shapelet, or when a leg's fit leaves the gate. */
	std::optional<Proposal> propose(MoveContext& ctx, model::Id t);
	void finish(MoveContext& ctx, bool accepted);

   private:
	/** Sets t's leg width and texture, refits its legs to them (invented legs: squares of that
	 *  width and texture where they stand); false when a fit leaves the gate. */
	bool apply(MoveContext& ctx, double legWidth, double texture);

	model::Id m_table = model::NONE;
	model::Table m_old;
	std::vector<std::pair<model::Id, model::Leg>> m_savedLegs;
};
}  // namespace whiskermap::inference::moves
