#include <whiskermap/model/Wall.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::model
{
double Wall::length() const { return std::hypot(x1 - x0, y1 - y0); }

bool Wall::sameAs(const Wall& o, double eps) const
{
	const auto close = [eps](double u, double v) { return std::abs(u - v) <= eps; };
	return close(x0, o.x0) && close(y0, o.y0) && close(x1, o.x1) && close(y1, o.y1) && close(thickness, o.thickness) &&
		   close(texture, o.texture);
}

bool Wall::farFrom(double x, double y, double d) const
{
	// The slab lies within thickness / 2 of its centre line, the centre line within its box.
	const double grow = (thickness / 2 + d) * (1 + 1e-9) + 1e-12;
	return x < std::min(x0, x1) - grow || x > std::max(x0, x1) + grow || y < std::min(y0, y1) - grow ||
		   y > std::max(y0, y1) + grow;
}

OrientedRect Wall::rect() const
{
	return {(x0 + x1) / 2, (y0 + y1) / 2, std::atan2(y1 - y0, x1 - x0), length() / 2, thickness / 2};
}

Wall::Frame Wall::frame() const
{
	const double len = length(), ux = len > 0 ? (x1 - x0) / len : 1, uy = len > 0 ? (y1 - y0) / len : 0;
	// Long face side s: normal s * n with n = (-uy, ux); the caps: +-u.
	return {len, ux, uy, {std::atan2(ux, -uy), std::atan2(-ux, uy), std::atan2(uy, ux), std::atan2(-uy, -ux)}};
}

Wall::FaceHit Wall::face(const Frame& fr, double x, double y, int side) const
{
	// Unit direction u; the left normal n = (-uy, ux).
	const double ux = fr.ux, uy = fr.uy, dx = x - x0, dy = y - y0;
	const double along = ux * dx + uy * dy, offset = -uy * dx + ux * dy;  // offset along n
	FaceHit h;
	h.side = side;
	h.across = side * offset - thickness / 2;
	h.along = along;
	h.excess = std::max({0.0, -along, along - fr.len});
	h.normal = fr.normal[faceIndex(side)];
	return h;
}

Wall::FaceHit Wall::hit(const Frame& fr, double x, double y, int f) const
{
	if (f == 1 || f == -1) return face(fr, x, y, f);
	const double ux = fr.ux, uy = fr.uy, dx = x - x0, dy = y - y0;
	const double along = ux * dx + uy * dy, offset = -uy * dx + ux * dy;
	FaceHit h;
	h.side = f;
	h.across = f > 0 ? along - fr.len : -along;
	h.along = offset;
	h.excess = std::max(0.0, std::abs(offset) - thickness / 2);
	h.normal = fr.normal[faceIndex(f)];
	return h;
}

Wall::FaceHit Wall::nearestFace(double x, double y) const
{
	const Frame fr = frame();
	return face(fr, x, y, -fr.uy * (x - x0) + fr.ux * (y - y0) >= 0 ? 1 : -1);
}

double Wall::faceDistance(double x, double y, int side) const
{
	const FaceHit h = face(x, y, side);
	return std::hypot(h.across, h.excess);
}
}  // namespace whiskermap::model
