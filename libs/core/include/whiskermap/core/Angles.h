#pragma once

namespace whiskermap::core
{
/** Wraps an angle into (-pi, pi]. */
double wrapToPi(double a);

/** Smallest signed difference a - b, taken modulo `period` (2*pi for plain angles,
 *  pi for an object with 180 degree symmetry, pi/2 for a square), in (-period/2, period/2]. */
double angleDiff(double a, double b, double period);

/** Degrees to radians and back. */
constexpr double deg2rad(double d) { return d * 0.017453292519943295; }
constexpr double rad2deg(double r) { return r * 57.29577951308232; }
}  // namespace whiskermap::core
