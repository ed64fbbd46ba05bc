#pragma once
#include <whiskermap/world/Table.h>

#include <cstdint>

namespace whiskermap::maps
{
/** One object of the consolidated (lasting) map: per-pose MAP tables that agree, merged.
 *  The table's pose is the running mean of its members (yaw averaged modulo 180 degrees). */
struct TMapObject
{
	world::Table table;
	uint32_t support = 0;  ///< per-pose MAP tables merged into it
	uint32_t evidence = 0;  ///< poses, since it was first found, with a contact on one of its legs
	uint64_t contacts = 0;  ///< contacts within the evidence margin of one of its legs
	uint8_t legMask = 0;  ///< bit k: leg k had such a contact
	/** Fraction of the poses with evidence on it whose MAP found it, in [0, 1]. */
	double existence() const { return evidence ? double(support) / evidence : 0.0; }

	// Running sums behind the mean pose.
	double sum_x = 0, sum_y = 0, sum_cos2 = 0, sum_sin2 = 0;
};
}  // namespace whiskermap::maps
