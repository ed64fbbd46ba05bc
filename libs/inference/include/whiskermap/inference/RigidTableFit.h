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
 *  the data association is the model's, the geometry the known table's. A compass
 *  search over (x, y, yaw) from the table's own pose, down to 0.01 mm at the corners; legs
 *  not at a corner (corner < 0) are left out. Returns the table with that pose (size,
 *  texture unchanged); a table without legs keeps its pose. */
model::Table fitRigidTable(const model::LastingState& s, model::Id t, const model::ModelParams& p);
}  // namespace whiskermap::inference
