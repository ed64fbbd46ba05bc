#pragma once
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/SweptGrid.h>
#include <whiskermap/model/Wall.h>

namespace whiskermap::model
{
/** Negative evidence for a wall from the map's swept grid (eq. 25, ours; doc/model.md,
 *  "Free space for walls in the lasting map"). The lasting map keeps no sectors, only the
 *  grid's counts per cell: the sweeps whose shafts crossed the cell without touching there
 *  (passes P_c) and those that touched in it (T_c). A wall's centre line crossing a cell
 *  that was swept and never touched is unlikely: a shaft crossing such a cell crosses the
 *  slab there with probability at least 1/2 (the slab spans the cell from side to side; a
 *  shaft clipping a corner may miss it) and then touches it unless it misses (p_miss), so
 *
 *      phi_g(W) = prod over cells c on W's centre line with T_c = 0 of ((1 + p_miss) / 2)^P_c
 *
 *  against 1 without the wall (a free cell passes every sweep). Cells with a touch count
 *  nothing (the wall's own contacts are scored by eq. 22, and a touch says the cell is not
 *  empty). */
struct GridFreeSpace
{
	/** log phi_g(W) (eq. 25); 0 when the wall crosses no swept, untouched cell. */
	static double logWallFactor(const Wall& w, const SweptGrid& grid, const ModelParams& p);
};
}  // namespace whiskermap::model
