#pragma once
#include <whiskermap/model/Factors.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/SweptGrid.h>
#include <whiskermap/model/Table.h>
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

	/** Eq. 27 (ours; doc/model.md, "Free space for legs in the lasting map"): a square leg of
	 *  side `w` centred on (x, y) whose neighbourhood (every cell within w / 2 + 2 sigma_r of
	 *  the centre, where its own contacts would fall) was never touched pays, per pass P_c of
	 *  the centre's cell, log(1 - (1 - p_miss) h) with h = min(1, w / (2 cell)): half the
	 *  chance (Cauchy-Crofton: perimeter over perimeter, w / cell) that a line crossing the
	 *  cell crosses the square, a shaft being a segment. 0 when any of those cells holds a
	 *  touch or the centre's cell was never passed. */
	static double logLegFactor(double x, double y, double w, const SweptGrid& grid, const ModelParams& p);
	/** Eq. 27 for the leg each empty corner of `t` implies (counts[k] == 0): a square of the
	 *  table's leg width centred on the corner. */
	static double logEmptyCorners(const Table& t, const CornerCounts& counts, const SweptGrid& grid, const ModelParams& p);
};
}  // namespace whiskermap::model
