#pragma once

namespace whiskermap::obs
{
/** Negative evidence of one whisker in one sweep, in world coordinates: the circular sector
 *  its shaft swept without touching anything. The shaft (length `radius`, pivot (x, y))
 *  turned from its start angle to where it stopped: its contact angle when it touched, else
 *  the end of the sweep. Every shaft position before the stop touched nothing, so the open
 *  sector holds no obstacle; the touched object lies beyond the stop ray. The angles come
 *  from the actuator, not from the noisy radial reading: the sector is exact given the pose. */
struct SweptSector
{
	double x = 0;  ///< pivot, metres (world frame)
	double y = 0;
	double radius = 0;  ///< shaft length, metres
	double from = 0;  ///< the sector runs counter-clockwise from this angle (radians, world)...
	double span = 0;  ///< ...through this many radians (> 0)

	/** How deep the point lies inside the sector, metres: its distance to the sector's
	 *  boundary (the arc and the two bounding rays; the pivot for a ray more than 90 degrees
	 *  away), 0 outside. */
	double depth(double px, double py) const;
};
}  // namespace whiskermap::obs
