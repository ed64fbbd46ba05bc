#include <whiskermap/obs/SweptSector.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::obs
{
double SweptSector::depth(double px, double py) const
{
	const double dx = px - x, dy = py - y;
	const double rho = std::sqrt(dx * dx + dy * dy);
	if (rho >= radius || rho == 0) return 0;
	double a = std::atan2(dy, dx) - from;
	a -= 2 * M_PI * std::floor(a / (2 * M_PI));  // in [0, 2 pi)
	if (a > span) return 0;
	// Distance to the two bounding rays (the perpendicular one, or the pivot beyond 90 deg).
	auto toRay = [&](double angle) { return angle >= M_PI / 2 ? rho : rho * std::sin(angle); };
	return std::min({radius - rho, toRay(a), toRay(span - a)});
}
}  // namespace whiskermap::obs
