#pragma once
#include <whiskermap/world/Table.h>

#include <cmath>
#include <cstdint>

namespace whiskermap::maps
{
/** One object of a map as written to map_tables.csv / map_candidates.csv (doc/outputs.md). */
struct TMappedObject
{
	world::Table table;  ///< pose and (known) size
	double existence = 0;  ///< posterior existence probability (lasting map), or the vote (per-pose mode)
	uint64_t contacts = 0;  ///< contacts its legs explain (per-pose mode: contacts seen on its legs)
	uint32_t legs = 0;  ///< distinct legs (corners, 0..4) with at least one contact
	/** The standard deviations of its pose (metres, metres, radians: the lasting map's pose
	 *  spread, when asked for: CHierarchicalObjectMap::mapObjects); NaN when not computed. */
	double sd_x = NAN, sd_y = NAN, sd_yaw = NAN;
};
}  // namespace whiskermap::maps
