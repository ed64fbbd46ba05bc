#pragma once
#include <whiskermap/inference/RandomScan.h>
#include <whiskermap/model/ModelParams.h>

namespace whiskermap::inference::moves
{
/** The random scan of the library's own moves on continuous poses (doc/sampler.md, "Random
 *  scan of the library's moves"): each move draws its target uniformly and adds the log
 *  probability of that draw, and of its reverse's draw from the new board, to the Proposal's
 *  densities, so that with the reversible-jump acceptance at finite beta (stochastic refits:
 *  MoveContext::stochasticRefits) the chain targets P^beta over tables and legs, walls held
 *  fixed. Moves (weight 1 each; a move and its reverse together):
 *  - leg birth: half the time birthFor(s), s uniform among the shapelets and unexplained,
 *    else birthAtCorner(t), t uniform among the tables / leg death: l uniform among the legs;
 *  - table birth: from l uniform among the legs / table death: t uniform among the tables;
 *    and the same pair completed (TableBirthDeath's `complete`: the birth invents the legs
 *    of its empty corners, the death takes them);
 *  - table switch: t uniform among the tables, TableBirthDeath::rebirth (its own reverse);
 *  - link: s uniform among the shapelets on a leg, to a leg uniform among the others within
 *    the parent gate of s (its own reverse);
 *  - split: s uniform among the shapelets on a leg / merge: l uniform among the legs, then
 *    `other` uniform among SplitMerge::candidates(l);
 *  - leg refit, table refit (and table resize with the model key `size_moves`), leg reparent:
 *    a hypothesis uniform among its kind (their own reverses).
 *  A move with no reverse declares logReverse = -inf and is never accepted: the chain stays
 *  exact and only loses those moves. `params` must outlive the scan. */
RandomScan libraryScan(const model::ModelParams& params);
}  // namespace whiskermap::inference::moves
