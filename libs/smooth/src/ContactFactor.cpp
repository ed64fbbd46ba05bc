#include <whiskermap/core/Angles.h>
#include <whiskermap/smooth/ContactFactor.h>

#include <Eigen/Geometry>
#include <cmath>

namespace whiskermap::smooth
{
double ContactFactor::residual(
	const Eigen::Vector3d& x, const Eigen::Vector2d& d, Eigen::Vector3d* Jx, Eigen::Vector2d* Jd) const
{
	const double c = std::cos(x[2]), s = std::sin(x[2]);
	const Eigen::Vector2d w(c * p.x() - s * p.y() + x[0], s * p.x() + c * p.y() + x[1]);
	if (Jx) *Jx = Eigen::Vector3d(n.x(), n.y(), n.x() * (-s * p.x() - c * p.y()) + n.y() * (c * p.x() - s * p.y())) / sigma;
	if (Jd) *Jd = -n / sigma;
	return (n.dot(w - d) - offset) / sigma;  // eq. S3
}

std::optional<ContactFactor> ContactFactor::associate(
	const baseline::Contact& c, size_t pose, const Eigen::Vector3d& x, const std::vector<world::Obstacle>& solids,
	const std::vector<size_t>& groupOf, const std::vector<Eigen::Vector2d>& shifts, double gate, double normalGate,
	double floor)
{
	const Eigen::Rotation2Dd R(x[2]);
	const Eigen::Vector2d w = R * c.p + x.head<2>();
	const double normal = x[2] + c.normal;
	std::optional<ContactFactor> best;
	double bestDistance = gate;
	for (size_t i = 0; i < solids.size(); i++)
	{
		const auto& o = solids[i];
		const Eigen::Vector2d d = shifts[groupOf[i]];
		const Eigen::Vector2d local = w - d;  // the contact against the solid as mapped
		if (o.distance(local) > gate) continue;
		for (int k = 0; k < 4; k++)
		{
			const Eigen::Vector2d n = o.edgeNormal(k);
			if (std::abs(core::angleDiff(normal, std::atan2(n.y(), n.x()), 2 * M_PI)) > normalGate) continue;
			const Eigen::Vector2d& q0 = o.corners[static_cast<size_t>(k)];
			const Eigen::Vector2d& q1 = o.corners[static_cast<size_t>((k + 1) % 4)];
			const Eigen::Vector2d e = q1 - q0;
			const double u = std::clamp((local - q0).dot(e) / std::max(e.squaredNorm(), 1e-18), 0.0, 1.0);
			const double distance = (local - (q0 + u * e)).norm();
			if (distance >= bestDistance) continue;
			bestDistance = distance;
			ContactFactor f;
			f.pose = pose, f.solid = i, f.group = groupOf[i], f.p = c.p, f.n = n, f.offset = n.dot(q0);
			const double along = c.sigma_r * n.dot(R * c.shaft);
			f.sigma = std::sqrt(along * along + floor * floor);
			best = f;
		}
	}
	return best;
}
}  // namespace whiskermap::smooth
