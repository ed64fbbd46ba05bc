#include <whiskermap/core/Angles.h>

#include <cmath>

namespace whiskermap::core
{
double angleDiff(double a, double b, double period)
{
	double d = a - b;
	if (d > -period / 2 && d <= period / 2) return d;  // already in range: what fmod would give
	d = std::fmod(d, period);
	if (d <= -period / 2) d += period;
	if (d > period / 2) d -= period;
	return d;
}

double wrapToPi(double a) { return angleDiff(a, 0.0, 2 * M_PI); }
}  // namespace whiskermap::core
