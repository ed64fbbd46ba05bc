#pragma once
#include <whiskermap/model/Blackboard.h>

#include <vector>

namespace whiskermap::inference
{
/** Table hypotheses built from legs, and the table death that goes with them: shared by the
 *  sampler's parent proposals (doc/sampler.md) and the existence estimate (TableExistence). */

/** The table of class `cls` (its size, leg width and texture) with `leg` at `corner`, turned
 *  by `turn` from its yaw. */
model::Table tableWithLegAt(const model::ModelParams& p, const model::Leg& leg, int corner, double turn, int cls);

/** Appends to `out` the tables of every class (tablesForPairs per class, in catalogue order). */
void tablesForPairs(const model::Blackboard& bb, model::Id l, std::vector<model::Table>& out);
/** Appends to `out` the tables of class `cls` with leg `l` and another leg of the board
 *  near it at two of their corners (pair distance within 2 gates of the corners' distance,
 *  the other leg's texture within 5 sigma_tau of the table's), each fitted to the pair
 *  (fitTable): the table and its mirror image for every match. */
void tablesForPairs(const model::Blackboard& bb, model::Id l, int cls, std::vector<model::Table>& out);

/** Fills `out` with the legs other than `l` that table `t` would adopt (l at its nearest
 *  corner, then at each other corner the leg nearest to it within the parent gate, if any); returns
 *  their number. */
size_t adoptable(const model::Blackboard& bb, const model::Table& t, model::Id l, std::vector<model::Id>& out);

/** Removes `table` and then those of its legs that explain nothing (the prune would);
 *  returns the change of logJoint (eq. 20 of each, in turn). `orphans` is scratch. */
double removeTableAndOrphans(model::Blackboard& bb, model::Id table, std::vector<model::Id>& orphans);
}  // namespace whiskermap::inference
