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

double SweptSpace::segmentPenetration(const obs::SweptSector& s, double ax, double ay, double bx, double by)
{
	const double ex = bx - ax, ey = by - ay;
	const auto depthAt = [&](double t) { return s.depth(ax + t * ex, ay + t * ey); };
	if (s.span > M_PI)  // not convex: sample
	{
		double d = 0;
		for (int i = 0; i <= 64; i++) d = std::max(d, depthAt(i / 64.0));
		return d;
	}
	// The part inside: the disc |p - pivot| < radius and the wedge between the two rays.
	const double fx = ax - s.x, fy = ay - s.y;
	double t0 = 0, t1 = 1;
	const double qa = ex * ex + ey * ey, qb = fx * ex + fy * ey, qc = fx * fx + fy * fy - s.radius * s.radius;
	if (qa == 0) return s.depth(ax, ay);  // a point
	const double disc = qb * qb - qa * qc;
	if (disc <= 0) return 0;
	const double root = std::sqrt(disc);
	t0 = std::max(t0, (-qb - root) / qa), t1 = std::min(t1, (-qb + root) / qa);
	// Left of the first ray (cross(u_from, p) >= 0) and right of the last (cross(p, u_to) >= 0):
	// each a linear inequality in t, g + t h >= 0.
	const auto keep = [&](double g, double h) {
		if (h > 0) t0 = std::max(t0, -g / h);
		else if (h < 0) t1 = std::min(t1, -g / h);
		else if (g < 0) t1 = -1;  // parallel and outside
	};
	const double c0 = std::cos(s.from), s0 = std::sin(s.from), c1 = std::cos(s.from + s.span), s1 = std::sin(s.from + s.span);
	keep(c0 * fy - s0 * fx, c0 * ey - s0 * ex);
	keep(fx * s1 - fy * c1, ex * s1 - ey * c1);
	if (t0 >= t1) return 0;
	// Golden section for the maximum of the concave depth on [t0, t1].
	constexpr double G = 0.6180339887498949;
	double lo = t0, hi = t1, m1 = hi - G * (hi - lo), m2 = lo + G * (hi - lo), d1 = depthAt(m1), d2 = depthAt(m2);
	for (int i = 0; i < 40; i++)
		if (d1 < d2)
			lo = m1, m1 = m2, d1 = d2, m2 = lo + G * (hi - lo), d2 = depthAt(m2);
		else
			hi = m2, m2 = m1, d2 = d1, m1 = hi - G * (hi - lo), d1 = depthAt(m1);
	return std::max(d1, d2);
}

namespace
{
double logMissed(double d, const ModelParams& p)
{
	const double q = p.free_space_p_miss;
	return std::log(q + (1 - q) * std::exp(-d * d / (p.sigma_r * p.sigma_r)));  // eq. 21
}
}  // namespace

double SweptSpace::logFactor(const OrientedRect& r, const ModelParams& p) const
{
	if (!p.free_space) return 0;
	double sum = 0;
	for (const obs::SweptSector& s : m_sectors)
	{
		const double d = penetration(s, r);
		if (d > 0) sum += logMissed(d, p);
	}
	return sum;
}

double SweptSpace::logWallFactor(const Wall& w, const ModelParams& p) const
{
	if (!p.free_space || m_sectors.empty()) return 0;
	const Wall::Frame fr = w.frame();
	const double nx = -fr.uy * w.thickness / 2, ny = fr.ux * w.thickness / 2;  // to the left face
	const double reach = fr.len / 2 + w.thickness / 2;  // every slab point lies within this of the centre
	const double mx = (w.x0 + w.x1) / 2, my = (w.y0 + w.y1) / 2;
	double sum = 0;
	for (const obs::SweptSector& s : m_sectors)
	{
		if (std::hypot(s.x - mx, s.y - my) >= s.radius + reach) continue;
		double d = 0;
		for (const double k : {0.0, 1.0, -1.0})
			d = std::max(d, segmentPenetration(s, w.x0 + k * nx, w.y0 + k * ny, w.x1 + k * nx, w.y1 + k * ny));
		if (d > 0) sum += logMissed(d, p);
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
