#include <whiskermap/model/Densities.h>
#include <whiskermap/model/SweptSpace.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::model
{
double SweptSpace::penetration(const obs::SweptSector& s, const OrientedRect& r)
{
	// Every point of the rectangle lies within h of its centre: a sector beyond that reach, or
	// whose angles miss the centre's by more than asin(h / distance), cannot hold any of them.
	const double h = std::hypot(r.hx, r.hy), reach = s.radius + h;
	const double dx = s.x - r.cx, dy = s.y - r.cy, d2 = dx * dx + dy * dy;
	if (d2 >= reach * reach) return 0;
	if (d2 > h * h)
	{
		const double margin = std::asin(h / std::sqrt(d2));
		double a = std::atan2(-dy, -dx) - s.from;
		a -= 2 * M_PI * std::floor(a / (2 * M_PI));  // in [0, 2 pi)
		if (a > s.span + margin && a < 2 * M_PI - margin) return 0;
	}
	const double c = std::cos(r.theta), sn = std::sin(r.theta);
	const auto at = [&](double u, double v) { return s.depth(r.cx + c * u - sn * v, r.cy + sn * u + c * v); };
	// The pivot in the rectangle's frame, clamped onto it: the rectangle's point nearest the pivot.
	const double pu = std::clamp(c * dx + sn * dy, -r.hx, r.hx), pv = std::clamp(-sn * dx + c * dy, -r.hy, r.hy);
	double d = std::max(at(0, 0), at(pu, pv));
	for (const double u : {-r.hx, 0.0, r.hx})
		for (const double v : {-r.hy, 0.0, r.hy}) d = std::max(d, at(u, v));
	return d;
}

double SweptSpace::logFactor(const OrientedRect& r, const ModelParams& p) const
{
	if (!p.free_space) return 0;
	const double q = p.free_space_p_miss;
	double sum = 0;
	for (const obs::SweptSector& s : m_sectors)
	{
		const double d = penetration(s, r);
		if (d > 0) sum += std::log(q + (1 - q) * std::exp(-d * d / (p.sigma_r * p.sigma_r)));  // eq. 21
	}
	return sum;
}

double SweptSpace::logEmptyCorners(const Table& t, const CornerCounts& counts, const ModelParams& p) const
{
	if (!p.free_space || m_sectors.empty()) return 0;
	double x[4], y[4], sum = 0;
	tableCorners(t, p, x, y);
	for (int k = 0; k < 4; k++)
		if (counts[static_cast<size_t>(k)] == 0)
			sum += logFactor({x[k], y[k], t.theta, t.leg_width / 2, t.leg_width / 2}, p);
	return sum;
}
}  // namespace whiskermap::model
