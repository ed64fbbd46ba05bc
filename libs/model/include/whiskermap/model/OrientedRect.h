#pragma once

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

	/** Exact distance from a point to face k (the side whose outward normal is
	 *  theta + k pi/2), a segment: 0, 2 across the x axis; 1, 3 across the y axis. */
	double faceDistance(double x, double y, int k) const;

	/** True when the two rectangles share interior points (separating-axis test; touching
	 *  edges do not count). */
	bool overlaps(const OrientedRect& o) const;
};
}  // namespace whiskermap::model
