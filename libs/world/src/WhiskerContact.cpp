#include <whiskermap/world/WhiskerContact.h>

#include <cmath>

namespace whiskermap::world
{
namespace
{
Eigen::Vector2d dirOf(double a) { return {std::cos(a), std::sin(a)}; }
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
	return a.x() * b.y() - a.y() * b.x();
}

/** Nearest crossing of the shaft (at a fixed angle) with obstacle edges. */
std::optional<WhiskerContact> castShaft(
	const Eigen::Vector2d& pivot, double length, double angle,
	const std::vector<Obstacle>& obstacles)
{
	const Eigen::Vector2d d = dirOf(angle);
	std::optional<WhiskerContact> best;
	for (size_t i = 0; i < obstacles.size(); i++)
		for (int k = 0; k < 4; k++)
		{
			const auto& o = obstacles[i];
			const Eigen::Vector2d a = o.corners[k], e = o.corners[(k + 1) % 4] - a;
			const Eigen::Vector2d n = o.edgeNormal(k);
			if (n.dot(d) >= 0) continue;  // the shaft meets only faces that face it
			const double den = cross(d, e);
			if (den == 0) continue;
			const double r = cross(a - pivot, e) / den;  // distance along the shaft
			const double s = cross(a - pivot, d) / den;  // position along the edge
			if (r < 0 || r > length || s < 0 || s > 1) continue;
			if (!best || r < best->r)
				best = WhiskerContact{angle, r, pivot + r * d, std::atan2(n.y(), n.x()),
									  static_cast<int>(i)};
		}
	return best;
}
}  // namespace

std::optional<WhiskerContact> WhiskerContact::first(
	const Eigen::Vector2d& pivot, double length, double a0, double a1,
	const std::vector<Obstacle>& obstacles)
{
	// Already touching when the whisk starts (always the case for a fixed whisker).
	if (auto c = castShaft(pivot, length, a0, obstacles); c || a0 == a1) return c;

	const double span = std::abs(a1 - a0), sgn = a1 > a0 ? 1.0 : -1.0;
	// Progress of the sweep (0..span) at which the shaft points at angle a.
	auto progress = [&](double a) {
		double u = std::fmod(sgn * (a - a0), 2 * M_PI);
		return u < 0 ? u + 2 * M_PI : u;
	};
	double bestU = INFINITY;
	std::optional<WhiskerContact> best;
	// Whether the touch at p, at bearing `a` from the pivot, comes first so far: then it is
	// kept, and the caller sets its normal (worked out only for such touches).
	auto earliest = [&](const Eigen::Vector2d& p, double a, double range, int index) {
		const double u = progress(a);
		if (u > span || u >= bestU) return false;
		bestU = u;
		best = WhiskerContact{a0 + sgn * u, range, p, 0, index};
		return true;
	};

	for (size_t i = 0; i < obstacles.size(); i++)
	{
		const auto& o = obstacles[i];
		const Eigen::Vector2d normals[4] = {o.edgeNormal(0), o.edgeNormal(1), o.edgeNormal(2), o.edgeNormal(3)};
		for (int k = 0; k < 4; k++)
		{
			const Eigen::Vector2d a = o.corners[k], e = o.corners[(k + 1) % 4] - a;
			const Eigen::Vector2d& n = normals[k];
			// (1) a corner sweeps onto the shaft. The face reported is the adjacent face
			// that most opposes the shaft's motion (the one it presses against).
			const double r = (a - pivot).norm();
			if (r > 0 && r <= length)
			{
				const double ac = std::atan2(a.y() - pivot.y(), a.x() - pivot.x());
				if (earliest(a, ac, r, static_cast<int>(i)))
				{
					const Eigen::Vector2d motion = sgn * Eigen::Vector2d(-std::sin(ac), std::cos(ac));
					const Eigen::Vector2d& nPrev = normals[(k + 3) % 4];
					const Eigen::Vector2d& nf = n.dot(motion) < nPrev.dot(motion) ? n : nPrev;
					best->normal = std::atan2(nf.y(), nf.x());
				}
			}
			// (2) the tip (circle of radius `length`) meets the edge.
			const Eigen::Vector2d f = a - pivot;
			const double A = e.squaredNorm(), B = 2 * f.dot(e), C = f.squaredNorm() - length * length;
			const double disc = B * B - 4 * A * C;
			if (disc < 0) continue;
			for (double sign : {-1.0, 1.0})
			{
				const double t = (-B + sign * std::sqrt(disc)) / (2 * A);
				if (t < 0 || t > 1) continue;
				const Eigen::Vector2d q = a + t * e;
				if (earliest(q, std::atan2(q.y() - pivot.y(), q.x() - pivot.x()), length, static_cast<int>(i)))
					best->normal = std::atan2(n.y(), n.x());
			}
		}
	}
	return best;
}
}  // namespace whiskermap::world
