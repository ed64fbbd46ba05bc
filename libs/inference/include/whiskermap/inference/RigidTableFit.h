#pragma once
#include <whiskermap/model/Id.h>
#include <whiskermap/model/LastingState.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/Table.h>

namespace whiskermap::inference
{
/** The pose of lasting table `t` with its legs rigid at its corners (eq. 6 with no slack) that
 *  best explains every contact its legs explain (eq. 7 under `p`, summed over their explicit
 *  contacts and their folded evidence; the lasting map passes its model with shaft noise on):
 *  the data association is the model's, the geometry the known table's. Newton steps on
 *  the quadratic through 10 scores around the pose (from the table's own pose, until a step
 *  is below 0.01 mm), or a compass search down to 0.01 mm at the corners where the score is
 *  not a concave quadratic there (turns pivot about the legs' mean corner); legs
 *  not at a corner (corner < 0) are left out. Returns the table with that pose (size,
 *  texture unchanged); a table without legs keeps its pose. */
model::Table fitRigidTable(const model::LastingState& s, model::Id t, const model::ModelParams& p);

/** The score fitRigidTable maximises: eq. 7 under `p` summed over every contact (explicit and
 *  folded) of lasting table t's legs at a corner, each leg rigid at its corner of `table`
 *  (eq. 6 with no slack) and turned with it. */
double rigidTableScore(
	const model::LastingState& s, model::Id t, const model::Table& table, const model::ModelParams& p);
}  // namespace whiskermap::inference
