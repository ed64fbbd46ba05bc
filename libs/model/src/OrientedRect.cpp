#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>
#include <whiskermap/model/OrientedRect.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::model
{
OrientedRect::PerimeterHit OrientedRect::perimeter(double x, double y) const
{
	const auto [s, c] = core::cachedSinCos(theta);
	const double dx = x - cx, dy = y - cy;
	const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
	// Signed excess beyond each pair of faces: > 0 outside that slab.
	const double sx = std::abs(lx) - hx, sy = std::abs(ly) - hy;
	const double distance = (sx > 0 || sy > 0) ? std::hypot(std::max(sx, 0.0), std::max(sy, 0.0))
											   : -std::max(sx, sy);
	// Nearest face: the one whose slab the point is furthest out of (least deep inside).
	const double faceNormal = sx >= sy ? theta + (lx >= 0 ? 0.0 : M_PI)
									   : theta + (ly >= 0 ? M_PI_2 : -M_PI_2);
	return {distance, core::wrapToPi(faceNormal)};
}

double OrientedRect::faceDistance(double x, double y, int k) const
{
	const auto [s, c] = core::cachedSinCos(theta);
	const double dx = x - cx, dy = y - cy;
	const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
	// Along the face's normal (u) and along the face (v), in the face's own frame.
	const double u = k == 0 ? lx : k == 1 ? ly : k == 2 ? -lx : -ly;
	const double v = k % 2 == 0 ? ly : lx;
	const double halfNormal = k % 2 == 0 ? hx : hy, halfAlong = k % 2 == 0 ? hy : hx;
	return std::hypot(u - halfNormal, std::max(std::abs(v) - halfAlong, 0.0));
}

bool OrientedRect::overlaps(const OrientedRect& o) const
{
	const double dx = o.cx - cx, dy = o.cy - cy;
	// Centres further apart than the two circumradii: apart (what the axes below find, cheaper).
	const double reach = std::sqrt(hx * hx + hy * hy) + std::sqrt(o.hx * o.hx + o.hy * o.hy);
	if (dx * dx + dy * dy > reach * reach) return false;
	const double axes[4] = {theta, theta + M_PI_2, o.theta, o.theta + M_PI_2};
	const core::SinCos self = core::cachedSinCos(theta), other = core::cachedSinCos(o.theta);
	for (const double a : axes)
	{
		const core::SinCos u = core::cachedSinCos(a);
		const double ux = u.cos, uy = u.sin;  // (not a structured binding: lambdas capture it only from C++20)
		// Projected half-length of a rectangle (yaw t, half-extents h) on axis u.
		const auto radius = [&](const core::SinCos& t, double hxx, double hyy) {
			return hxx * std::abs(t.cos * ux + t.sin * uy) + hyy * std::abs(-t.sin * ux + t.cos * uy);
		};
		if (std::abs(dx * ux + dy * uy) >= radius(self, hx, hy) + radius(other, o.hx, o.hy)) return false;
	}
	return true;
}
}  // namespace whiskermap::model
