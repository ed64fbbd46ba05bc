#pragma once
#include <whiskermap/model/Blackboard.h>

namespace whiskermap::model
{
/** The unnormalised log posterior of a blackboard and its local (Markov-blanket) pieces.
 *
 *  Every present table or leg is a cell (eq. 19) with density p(H | pa(H)) (eq. 12: its
 *  explicit parent's term plus the null cause); absent cells count 1 (their 1 - P ~ 1 is
 *  dropped). Shapelets are data: their densities p(S | pa(S)) enter uncelled. A leg's folded
 *  contacts (LegEvidence) enter as sum log p(S | L) - log c_S: relative to their null cause,
 *  which is a constant while they are folded. Factors: phi_a and phi_b per table (eqs. 15,
 *  17), phi_c per overlapping same-type pair (eq. 16), context objects included. */

/** log P(B, shapelets) up to a constant (eq. 14). Visits every hypothesis once; overlaps
 *  through the spatial hash. */
double logJoint(const Blackboard& bb);

/** The terms of logJoint that involve table `table` or its legs (their densities, evidence,
 *  shapelets, factors and overlaps): a change confined to the poses of a table and its legs
 *  changes logJoint by exactly the change of this sum. */
double logJointAround(const Blackboard& bb, Id table);

/** Change of logJoint when leg `leg`, currently without a parent or with `table`, is linked
 *  to `table` rather than to nothing: its eq. 12 density and the table's phi_a, phi_b.
 *  0 for table == NONE. */
double logLegLinkGain(const Blackboard& bb, Id leg, Id table);

/** Same for shapelet `s` and `leg` (eq. 12 with eqs. 7, 9). 0 for leg == NONE. */
double logShapeletLinkGain(const Blackboard& bb, size_t s, Id leg);

/** log p(S | pa(S)) of shapelet s as the board links it (eq. 12): its leg (eq. 7), its wall
 *  (eq. 22) or neither, or'ed with the null cause (eq. 9). */
double logShapeletLinked(const Blackboard& bb, size_t s);

/** Local log-odds of a present hypothesis given its Markov blanket (eq. 20):
 *  logJoint(B) - logJoint(B without H, H's children unlinked). Uses only H's parent,
 *  children, siblings and same-type neighbours (from the spatial hash). */
double logOddsTable(const Blackboard& bb, Id table);
double logOddsLeg(const Blackboard& bb, Id leg);
/** The same for a wall: its cell (eq. 23), its shapelets (eq. 22 against the null cause), its
 *  folded evidence and the legs standing in it (eq. 16). */
double logOddsWall(const Blackboard& bb, Id wall);

/** P^beta(H | mb(H)): the conditional of the annealed joint P^beta for a move with
 *  log-odds `logOdds` (eq. 20): 1 / (1 + exp(-beta * logOdds)). */
double annealedAcceptance(double logOdds, double beta);
}  // namespace whiskermap::model
