#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>
#include <utility>
#include <vector>

namespace whiskermap::inference::moves
{
/** Refit of a table and its legs (doc/sampler.md, "Moves"): twice (fit the table to its legs
 *  that explain shapelets, then refit those legs to their contacts and new corners), then
 *  its invented legs onto its corners. Judged on the exact change of logJoint
 *  (logJointAround). Deterministic (logForward = 0) with no reverse (logReverse = -inf)
 *  unless nothing moved (0). The resize (model key `size_moves`) is the same move with the
 *  table's size fitted too, after its pose, in each round (fitTableSize: eqs. 6 and 24).
 *  With broad proposals: one random-walk step of the table's pose (MoveContext::randomWalk),
 *  its legs that explain shapelets left where they are, logReverse = 0 (symmetric).
 *  Stochastic under the reversible-jump acceptance at finite beta (MoveContext::
 *  stochasticRefits), so that it has a reverse: the table's fit to its legs that explain
 *  shapelets plus N(0, leg_position_noise^2) per axis (and per size offset, for the resize)
 *  and N(0, MoveContext::tableAngleNoise^2) in yaw; those legs stay (their own refits move them), its
 *  invented legs move onto the new corners. logForward: the new table's density about the
 *  fit from the old board; logReverse: the old table's about the fit from the new board (-inf
 *  if an invented leg did not stand at its old corner). */
class TableRefit
{
   public:
	explicit TableRefit(bool resize = false) : m_resize(resize) {}

	/** nullopt (board unchanged) if no leg of t explains a shapelet or a leg's fit leaves
	 *  the gate. */
	std::optional<Proposal> propose(MoveContext& ctx, model::Id t);
	void finish(MoveContext& ctx, bool accepted);

   private:
	/** Fits the table from `start` to its legs that explain shapelets (then its size, for the
	 *  resize); false if none does. */
	bool fitToLegs(const MoveContext& ctx, const model::Table& start, model::Table& out);
	/** The stochastic refit (MoveContext::stochasticRefits). */
	std::optional<Proposal> drawn(MoveContext& ctx, model::Id t, double before);

	bool m_resize;
	model::Id m_table = model::NONE;
	model::Table m_old;
	std::vector<std::pair<model::Id, model::Leg>> m_savedLegs;
	std::vector<const model::Leg*> m_fitLegs;
	std::vector<int> m_fitCorners;
};
}  // namespace whiskermap::inference::moves
