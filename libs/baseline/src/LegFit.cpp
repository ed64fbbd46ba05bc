#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/baseline/LeastSquares.h>
#include <whiskermap/baseline/LegFit.h>

#include <cmath>
#include <complex>

namespace whiskermap::baseline
{
Eigen::Vector2d LegFit::pointedCentre(const Contact& c, double legWidth)
{
	return c.p - legWidth / 2 * Eigen::Vector2d(std::cos(c.normal), std::sin(c.normal));
}

LegFit LegFit::fit(const std::vector<Contact>& contacts, std::vector<size_t> members, const TBaselineParams& p)
{
	LegFit leg;
	leg.members = std::move(members);
	// Start: the centre the contacts point at, the yaw their normals agree on modulo 90 deg.
	Eigen::Vector2d pointed(0, 0);
	std::complex<double> quarter(0, 0);
	for (size_t i : leg.members)
	{
		pointed += pointedCentre(contacts[i], p.leg_width);
		quarter += std::polar(1.0, 4 * contacts[i].normal);
		leg.texture += contacts[i].texture;
	}
	const double n = double(leg.members.size());
	pointed /= n, leg.texture /= n;
	Eigen::Vector3d x(pointed.x(), pointed.y(), std::arg(quarter) / 4);

	std::vector<int> faces(leg.members.size());
	auto assignFaces = [&] {
		bool changed = false;
		for (size_t j = 0; j < faces.size(); j++)
		{
			const int f = FaceResidual::best(contacts[leg.members[j]], x.head<2>(), x[2], p).face;
			changed = changed || f != faces[j];
			faces[j] = f;
		}
		return changed;
	};
	const auto residuals = [&](const Eigen::Vector3d& v, std::vector<double>& out) {
		out.clear();
		for (size_t j = 0; j < faces.size(); j++)
		{
			const auto r = FaceResidual::on(contacts[leg.members[j]], v.head<2>(), v[2], faces[j], p);
			out.push_back(LeastSquares::huber(r.point));
			out.push_back(LeastSquares::huber(r.normal));
			out.push_back(LeastSquares::huber(r.beyond));
		}
		out.push_back((v[0] - pointed.x()) / p.leg_width);
		out.push_back((v[1] - pointed.y()) / p.leg_width);
	};
	assignFaces();
	LeastSquares::Result res;
	for (int round = 0; round < 4; round++)
	{
		res = LeastSquares::solve(x, residuals);
		x = res.x;
		if (!assignFaces()) break;
	}
	leg.centre = x.head<2>();
	leg.yaw = std::fmod(std::fmod(x[2], M_PI / 2) + M_PI / 2, M_PI / 2);
	leg.centreCovariance = res.covariance.topLeftCorner<2, 2>();
	// The fit's yaw std-dev trusts the face assignments; with noisy normals and few contacts
	// they can be wrong, so never claim better than the normals alone give.
	double sigmaPhi = 0;
	for (size_t i : leg.members) sigmaPhi += std::hypot(contacts[i].sigma_phi, p.angle_floor) / n;
	leg.yawSigma = std::max(std::sqrt(std::max(0.0, res.covariance(2, 2))), sigmaPhi / std::sqrt(n));
	int mask = 0;
	for (size_t j = 0; j < faces.size(); j++)
	{
		const auto r = FaceResidual::best(contacts[leg.members[j]], leg.centre, leg.yaw, p);
		leg.outliers += r.outlier(p);
		mask |= 1 << r.face;
	}
	for (int k = 0; k < 4; k++) leg.faces += (mask >> k) & 1;
	return leg;
}

bool LegFit::legShaped(const TBaselineParams& p) const
{
	return !members.empty() && double(outliers) <= p.outlier_fraction * double(members.size());
}
}  // namespace whiskermap::baseline
