#pragma once
#include <Eigen/Core>

namespace whiskermap::smooth
{
/** The odometry between two consecutive poses a, b = (x, y, yaw) of the path: the increment
 *  the odometry recorded, u, in a's frame, with its motion model's covariance C (eq. S2,
 *  doc/slam.md): r = S [R(yaw_a)^T (p_b - p_a) - u_xy ; wrap(yaw_b - yaw_a - u_yaw)], S^T S = C^-1. */
struct OdometryFactor
{
	Eigen::Vector3d u{0, 0, 0};
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< C, with the floor below
	Eigen::Matrix3d sqrtInfo = Eigen::Matrix3d::Identity();  ///< S

	/** From the increment and its covariance (a floor of 0.1 mm and 0.01 degree keeps an exact
	 *  odometry's zero covariance invertible). */
	OdometryFactor(const Eigen::Vector3d& increment, const Eigen::Matrix3d& covariance);

	/** The pose the increment leads to from a: where the residual is zero. */
	Eigen::Vector3d end(const Eigen::Vector3d& a) const;

	/** The whitened residual at (a, b), and its Jacobians with respect to a and b if asked for. */
	Eigen::Vector3d residual(
		const Eigen::Vector3d& a, const Eigen::Vector3d& b, Eigen::Matrix3d* Ja = nullptr,
		Eigen::Matrix3d* Jb = nullptr) const;
};
}  // namespace whiskermap::smooth
