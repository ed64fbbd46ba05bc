#pragma once
#include <cmath>

namespace whiskermap::core
{
/** angleDiff for a difference d = a - b outside (-period/2, period/2]: the out-of-line part
 *  (angleDiff itself handles differences under two periods, the usual case, the same way). */
double wrapDifference(double d, double period);

/** A remainder r in (-period, period) moved into (-period/2, period/2]: angleDiff's last step. */
inline double centred(double r, double period)
{
	if (r <= -period / 2) r += period;
	if (r > period / 2) r -= period;
	return r;
}

/** Smallest signed difference a - b, taken modulo `period` (2*pi for plain angles,
 *  pi for an object with 180 degree symmetry, pi/2 for a square), in (-period/2, period/2].
 *  Inline: the fits evaluate it tens of thousands of times per insertion, nearly always
 *  in range already (doc/benchmarks.md, "Lasting map"). */
inline double angleDiff(double a, double b, double period)
{
	const double d = a - b;
	if (d > -period / 2 && d <= period / 2) return d;  // already in range: what fmod would give
	const double r = std::abs(d);
	if (!(r < 2 * period)) return wrapDifference(d, period);
	return centred(std::copysign(r >= period ? r - period : r, d), period);  // fmod's exact remainder (Sterbenz)
}

/** Wraps an angle into (-pi, pi]. */
inline double wrapToPi(double a) { return angleDiff(a, 0.0, 6.283185307179586); }  // 2 pi, as M_PI * 2 rounds

/** Degrees to radians and back. */
constexpr double deg2rad(double d) { return d * 0.017453292519943295; }
constexpr double rad2deg(double r) { return r * 57.29577951308232; }
}  // namespace whiskermap::core
