#include <whiskermap/core/Angles.h>
#include <whiskermap/smooth/OdometryFactor.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <cmath>

namespace whiskermap::smooth
{
OdometryFactor::OdometryFactor(const Eigen::Vector3d& increment, const Eigen::Matrix3d& c) : u(increment)
{
	const Eigen::Vector3d floor(1e-4, 1e-4, core::deg2rad(0.01));
	covariance = c + Eigen::Matrix3d(floor.cwiseProduct(floor).asDiagonal());
	sqrtInfo = covariance.inverse().llt().matrixU();
}

Eigen::Vector3d OdometryFactor::end(const Eigen::Vector3d& a) const
{
	const double c = std::cos(a[2]), s = std::sin(a[2]);
	return {a[0] + c * u[0] - s * u[1], a[1] + s * u[0] + c * u[1], core::wrapToPi(a[2] + u[2])};
}

Eigen::Vector3d OdometryFactor::residual(
	const Eigen::Vector3d& a, const Eigen::Vector3d& b, Eigen::Matrix3d* Ja, Eigen::Matrix3d* Jb) const
{
	const double c = std::cos(a[2]), s = std::sin(a[2]);
	const double dx = b[0] - a[0], dy = b[1] - a[1];
	const Eigen::Vector3d e(c * dx + s * dy - u[0], -s * dx + c * dy - u[1], core::wrapToPi(b[2] - a[2] - u[2]));
	if (Ja)
	{
		Eigen::Matrix3d J;
		J << -c, -s, -s * dx + c * dy,  //
			s, -c, -c * dx - s * dy,  //
			0, 0, -1;
		*Ja = sqrtInfo * J;
	}
	if (Jb)
	{
		Eigen::Matrix3d J;
		J << c, s, 0,  //
			-s, c, 0,  //
			0, 0, 1;
		*Jb = sqrtInfo * J;
	}
	return sqrtInfo * e;
}
}  // namespace whiskermap::smooth
