#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <optional>

namespace whiskermap::inference::moves
{
/** Birth and death of a leg (doc/sampler.md, "Moves"). Two births, one death, each the
 *  other's reverse:
 *  - birthFor(s): a new free leg with shapelet s on its face (priming's Q(pa(S))): its pose
 *    is drawn, so logForward is the exact density of (x, y, yaw); the reverse is the death
 *    of that leg (logReverse = 0);
 *  - birthAtCorner(t): the missing leg at a uniformly chosen empty corner of table t, exactly
 *    at the corner (logForward = -log(empty corners)); the reverse is its death;
 *  - death(l): removes leg l (logForward = 0); its reverse is the birth that would make l
 *    again: birthFor(its one shapelet) for a free leg explaining one shapelet, with the
 *    texture and width a birth gives; birthAtCorner for a leg explaining nothing exactly at
 *    its table's corner; otherwise none (logReverse = -inf). Legs holding folded contacts
 *    are never proposed (their contacts would be lost). */
class LegBirthDeath
{
   public:
	Proposal birthFor(MoveContext& ctx, size_t s);
	std::optional<Proposal> birthAtCorner(MoveContext& ctx, model::Id t);
	std::optional<Proposal> death(MoveContext& ctx, model::Id l);
	/** Keeps the proposed board (accepted) or restores the one before (rejected). */
	void finish(MoveContext& ctx, bool accepted);

	/** log density of birthFor(s) proposing `leg`'s pose (x, y, yaw): yaw ~ N(normal,
	 *  leg_angle_noise^2), the centre half a width inward along -normal plus N(0, noise^2 I),
	 *  offset along the face uniform on [-w/2, w/2] (or fixed by an adjacent contact). A
	 *  zero noise makes that coordinate deterministic: its factor is left out. Broad
	 *  proposals: uniform on the disc of radius leg_width about s and on the yaw. */
	static double logBirthDensity(const MoveContext& ctx, size_t s, const model::Leg& leg);
	/** log of the probability that birthFor(s) proposes `leg`'s cell: logBirthDensity plus
	 *  log(2 delta) for each coordinate it draws at random (eq. 19's cell, as logJoint counts a
	 *  hypothesis). The moves' logForward and logReverse for a leg's birth or death: a
	 *  reversible-jump acceptance compares it with a change of logJoint, itself a cell's mass
	 *  (doc/sampler.md, "Cells, not densities"). */
	static double logBirthMass(const MoveContext& ctx, size_t s, const model::Leg& leg);
	/** The leg birthAtCorner invents at corner c of table `t` (id `parent`): exactly at the
	 *  corner, the table's yaw, leg width and texture. */
	static model::Leg atCorner(const model::ModelParams& p, const model::Table& t, int c, model::Id parent);
	/** True if `leg` stands exactly as atCorner puts it at its own corner of table `t`. */
	static bool standsAtCorner(const model::ModelParams& p, const model::Leg& leg, const model::Table& t);

   private:
	/** logBirthDensity, with the number of coordinates drawn at random. */
	static double logBirthDensity(const MoveContext& ctx, size_t s, const model::Leg& leg, int& drawn);

	model::Id m_leg = model::NONE;
	bool m_birth = false;
};
}  // namespace whiskermap::inference::moves
