#include <whiskermap/baseline/FaceResidual.h>
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
	const Eigen::Vector3d x(pointed.x(), pointed.y(), std::arg(quarter) / 4);

	std::vector<FaceResidual::Member> onLeg;
	for (size_t i : leg.members) onLeg.push_back({i, Eigen::Vector2d(0, 0)});
	const auto prior = [&](const Eigen::Vector3d& v, std::vector<double>& out) {
		out = {(v[0] - pointed.x()) / p.leg_width, (v[1] - pointed.y()) / p.leg_width};
	};
	const auto res = FaceResidual::fitPose(contacts, onLeg, x, p, prior);
	leg.centre = res.x.head<2>();
	leg.yaw = std::fmod(std::fmod(res.x[2], M_PI / 2) + M_PI / 2, M_PI / 2);
	leg.centreCovariance = res.covariance.topLeftCorner<2, 2>();
	// The fit's yaw std-dev trusts the face assignments; with noisy normals and few contacts
	// they can be wrong, so never claim better than the normals alone give.
	double sigmaPhi = 0;
	for (size_t i : leg.members) sigmaPhi += std::hypot(contacts[i].sigma_phi, p.angle_floor) / n;
	leg.yawSigma = std::max(std::sqrt(std::max(0.0, res.covariance(2, 2))), sigmaPhi / std::sqrt(n));
	int mask = 0;
	for (size_t i : leg.members)
	{
		const auto r = FaceResidual::best(contacts[i], leg.centre, leg.yaw, p);
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
