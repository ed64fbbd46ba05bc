#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/core/Angles.h>

#include <cmath>

namespace whiskermap::baseline
{
FaceResidual FaceResidual::on(
	const Contact& c, const Eigen::Vector2d& centre, double yaw, int face, const TBaselineParams& p)
{
	const double a = yaw + face * M_PI / 2;
	const Eigen::Vector2d n(std::cos(a), std::sin(a)), t(-n.y(), n.x());
	const Eigen::Vector2d d = c.p - centre;
	const double half = p.leg_width / 2;
	auto sigma = [&](const Eigen::Vector2d& dir) {
		const double along = c.sigma_r * dir.dot(c.shaft);
		return std::sqrt(along * along + p.position_floor * p.position_floor);
	};
	FaceResidual r;
	r.face = face;
	r.point = (n.dot(d) - half) / sigma(n);
	r.normal = core::angleDiff(c.normal, a, 2 * M_PI) / std::hypot(c.sigma_phi, p.angle_floor);
	r.beyond = std::max(0.0, std::abs(t.dot(d)) - half) / sigma(t);
	return r;
}

FaceResidual FaceResidual::best(const Contact& c, const Eigen::Vector2d& centre, double yaw, const TBaselineParams& p)
{
	FaceResidual best;
	double bestCost = INFINITY;
	for (int k = 0; k < 4; k++)
	{
		const auto r = on(c, centre, yaw, k, p);
		if (r.cost() < bestCost) best = r, bestCost = r.cost();
	}
	return best;
}

bool FaceResidual::outlier(const TBaselineParams& p) const
{
	return std::abs(point) > p.outlier_gate || std::abs(normal) > p.outlier_gate || beyond > p.outlier_gate;
}
}  // namespace whiskermap::baseline
