#include <whiskermap/core/Angles.h>

#include <cmath>

namespace whiskermap::core
{
namespace
{
/** std::fmod(d, period), exactly, without the library call when |d| < 16 periods: each
 *  step subtracts a power-of-two multiple m of the period from an r in [m, 2m), which is
 *  exact (Sterbenz), so r ends as the exact |d| - k period that fmod returns. */
double remainder(double d, double period)
{
	double r = std::abs(d);
	if (!(r < 16 * period)) return std::fmod(d, period);
	for (double m = 8 * period; m >= period; m /= 2)
		if (r >= m) r -= m;
	return std::copysign(r, d);
}
}  // namespace

double wrapDifference(double d, double period) { return centred(remainder(d, period), period); }
}  // namespace whiskermap::core
