#pragma once
#include <Eigen/Core>
#include <whiskermap/world/Obstacle.h>

namespace whiskermap::world
{
/** A ground-truth straight interior wall: a slab of the given thickness around the segment
 *  (x0, y0)-(x1, y1) (its centre line, no end caps), sensed like the arena's walls. */
struct Wall
{
	double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< centre line end points, metres
	double thickness = 0;  ///< metres, > 0
	double texture = 0;  ///< [0, 1]

	/** Length of the centre line, metres. */
	double length() const;
	/** The slab as a solid obstacle (table -1, leg -1: a wall). */
	Obstacle slab() const;
};
}  // namespace whiskermap::world
