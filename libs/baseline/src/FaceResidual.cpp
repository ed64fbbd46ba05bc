#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/core/Angles.h>

#include <Eigen/Geometry>
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

LeastSquares::Result FaceResidual::fitPose(
	const std::vector<Contact>& contacts, const std::vector<Member>& members, const Eigen::Vector3d& start,
	const TBaselineParams& p, const LeastSquares::Residuals& prior)
{
	auto centre = [](const Eigen::Vector3d& v, const Member& m) {
		return Eigen::Vector2d(v.head<2>() + Eigen::Rotation2Dd(v[2]) * m.offset);
	};
	std::vector<int> faces(members.size(), -1);
	auto assignFaces = [&](const Eigen::Vector3d& v) {
		bool changed = false;
		for (size_t j = 0; j < members.size(); j++)
		{
			const int f = best(contacts[members[j].contact], centre(v, members[j]), v[2], p).face;
			changed = changed || f != faces[j];
			faces[j] = f;
		}
		return changed;
	};
	const auto residuals = [&](const Eigen::Vector3d& v, std::vector<double>& out) {
		out.clear();
		for (size_t j = 0; j < members.size(); j++)
		{
			const auto r = on(contacts[members[j].contact], centre(v, members[j]), v[2], faces[j], p);
			out.push_back(LeastSquares::huber(r.point));
			out.push_back(LeastSquares::huber(r.normal));
			out.push_back(LeastSquares::huber(r.beyond));
		}
		if (!prior) return;
		std::vector<double> extra;
		prior(v, extra);
		out.insert(out.end(), extra.begin(), extra.end());
	};
	assignFaces(start);
	LeastSquares::Result res;
	res.x = start;
	for (int round = 0; round < 4; round++)
	{
		res = LeastSquares::solve(res.x, residuals);
		if (!assignFaces(res.x)) break;
	}
	return res;
}
}  // namespace whiskermap::baseline
