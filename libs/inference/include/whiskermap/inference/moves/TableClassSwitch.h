#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Class switch of a table (doc/sampler.md, "Moves"): another class of the catalogue, drawn
 *  uniformly among the K - 1 others, with the table's centre and yaw kept and its leg width,
 *  texture and size set to the new class's. Its own reverse: switching back is drawn with the
 *  same probability 1 / (K - 1), so logForward = logReverse (a table resized off its class's
 *  size has no reverse: switching back snaps it to the nominal size, logReverse = -inf). Judged on the exact change of
 *  logJoint around the table (logJointAround: its class prior, eq. 4; its legs, eqs. 5-6;
 *  its factors and overlaps, eqs. 15-17, 21). */
class TableClassSwitch
{
   public:
	/** nullopt (no draw, board unchanged) without a catalogue of two classes or more. */
	std::optional<Proposal> propose(MoveContext& ctx, model::Id t);
	/** The same to class `to` (tests, and the reverse). */
	Proposal switchTo(MoveContext& ctx, model::Id t, int to);
	void finish(MoveContext& ctx, bool accepted);

   private:
	model::Id m_table = model::NONE;
	model::Table m_old;
};
}  // namespace whiskermap::inference::moves
