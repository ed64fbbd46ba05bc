#pragma once
#include <cmath>

namespace whiskermap::model
{
/** A rectangle in the plane: centre, yaw, half-extents along its own axes. The geometry
 *  behind eq. 7 (distance to a leg's perimeter) and eq. 16 (overlap). */
struct OrientedRect
{
	double cx = 0, cy = 0, theta = 0;
	double hx = 0, hy = 0;  ///< half-extents along the rectangle's x and y axes

	/** Where a point is relative to the perimeter. */
	struct PerimeterHit
	{
		double distance;  ///< exact shortest distance to the perimeter (>= 0, inside too)
		double faceNormal;  ///< outward normal angle of the nearest face, in (-pi, pi]
	};
	PerimeterHit perimeter(double x, double y) const;
	/** True only when the point lies further than `d` from the perimeter: its centre is further
	 *  than d plus the half-diagonal (with a relative margin of 1e-9 for rounding). A cheap
	 *  reject before perimeter(); false says nothing. */
	bool fartherThan(double x, double y, double d) const
	{
		const double dx = x - cx, dy = y - cy, reach = d + std::sqrt(hx * hx + hy * hy);
		return dx * dx + dy * dy > reach * reach * (1 + 1e-9);
	}

	/** Exact distance from a point to face k (the side whose outward normal is
	 *  theta + k pi/2), a segment: 0, 2 across the x axis; 1, 3 across the y axis. */
	double faceDistance(double x, double y, int k) const;

	/** True when the two rectangles share interior points (separating-axis test; touching
	 *  edges do not count). */
	bool overlaps(const OrientedRect& o) const;
};
}  // namespace whiskermap::model
