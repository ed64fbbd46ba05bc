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

OrientedRect Wall::rect() const
{
	return {(x0 + x1) / 2, (y0 + y1) / 2, std::atan2(y1 - y0, x1 - x0), length() / 2, thickness / 2};
}

Wall::FaceHit Wall::face(double x, double y, int side) const
{
	const double len = length();
	// Unit direction u; the left normal n = (-uy, ux). A degenerate wall points along x.
	const double ux = len > 0 ? (x1 - x0) / len : 1, uy = len > 0 ? (y1 - y0) / len : 0;
	const double dx = x - x0, dy = y - y0;
	const double along = ux * dx + uy * dy, offset = -uy * dx + ux * dy;  // offset along n
	FaceHit h;
	h.side = side;
	h.across = side * offset - thickness / 2;
	h.along = along;
	h.excess = std::max({0.0, -along, along - len});
	h.normal = std::atan2(side * ux, -side * uy);  // side * n
	return h;
}

Wall::FaceHit Wall::hit(double x, double y, int f) const
{
	if (f == 1 || f == -1) return face(x, y, f);
	const double len = length();
	const double ux = len > 0 ? (x1 - x0) / len : 1, uy = len > 0 ? (y1 - y0) / len : 0;
	const double dx = x - x0, dy = y - y0;
	const double along = ux * dx + uy * dy, offset = -uy * dx + ux * dy;
	FaceHit h;
	h.side = f;
	h.across = f > 0 ? along - len : -along;
	h.along = offset;
	h.excess = std::max(0.0, std::abs(offset) - thickness / 2);
	h.normal = f > 0 ? std::atan2(uy, ux) : std::atan2(-uy, -ux);
	return h;
}

Wall::FaceHit Wall::nearestFace(double x, double y) const
{
	const double len = length();
	const double ux = len > 0 ? (x1 - x0) / len : 1, uy = len > 0 ? (y1 - y0) / len : 0;
	return face(x, y, -uy * (x - x0) + ux * (y - y0) >= 0 ? 1 : -1);
}

double Wall::faceDistance(double x, double y, int side) const
{
	const FaceHit h = face(x, y, side);
	return std::hypot(h.across, h.excess);
}
}  // namespace whiskermap::model
