#pragma once
#include <whiskermap/inference/RandomScan.h>
#include <whiskermap/inference/moves/PoseGrid.h>

namespace whiskermap::inference::moves
{
/** The exact random scan on a pose grid (doc/sampler.md, "Random scan on a pose grid"):
 *  grid leg birth/death, grid table birth/death, FixedPoseLink, LegReparent (on a leg drawn
 *  uniformly) and GridShift of tables and legs, with weights 1, 2, 1, 2, 2, 1, 1, 1 (deaths
 *  twice as often as births: the choice probabilities do not cancel). `grid`
 *  must outlive the scan. */
RandomScan gridScan(const PoseGrid& grid);
}  // namespace whiskermap::inference::moves
