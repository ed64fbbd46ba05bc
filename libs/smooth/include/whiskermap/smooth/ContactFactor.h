#pragma once
#include <Eigen/Core>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/world/Obstacle.h>

#include <optional>
#include <vector>

namespace whiskermap::smooth
{
/** One whisker contact on one face of a mapped solid (a table's leg or a wall): its distance
 *  across the face's line, in std-devs (eq. S3, doc/slam.md),
 *    r = (n . (R(yaw) p + t - q - d)) / sigma,  sigma^2 = (sigma_r n . R(yaw) shaft)^2 + floor^2,
 *  with p and shaft the contact and its whisker's direction in the robot frame (the reading
 *  is noisy along the shaft only), (t, yaw) the sweep's pose, q a point of the face and n its
 *  outward normal as mapped, and d the shift of the solid's group (PathSmoother). sigma is
 *  fixed when the contact is tied (associate), as the face is. */
struct ContactFactor
{
	size_t contact = 0;  ///< the contact's index in PathSmoother's input (set by the caller)
	size_t pose = 0;  ///< the sweep's index in the path
	size_t solid = 0;  ///< the solid tied to (index into the solids)
	size_t group = 0;  ///< the solid's group
	Eigen::Vector2d p{0, 0}, n{1, 0};
	double offset = 0;  ///< n . q
	double sigma = 1;

	/** The whitened residual at pose x and group shift d, and its Jacobians if asked for. */
	double residual(
		const Eigen::Vector3d& x, const Eigen::Vector2d& d, Eigen::Vector3d* Jx = nullptr,
		Eigen::Vector2d* Jd = nullptr) const;

	/** Ties robot-frame contact `c` of sweep `pose` seen from pose x to the nearest face of
	 *  `solids` (each shifted by its group's shift) whose outward normal is within
	 *  `normalGate` of the contact's and whose segment lies within `gate` of the contact;
	 *  nothing when no face qualifies. */
	static std::optional<ContactFactor> associate(
		const baseline::Contact& c, size_t pose, const Eigen::Vector3d& x, const std::vector<world::Obstacle>& solids,
		const std::vector<size_t>& groupOf, const std::vector<Eigen::Vector2d>& shifts, double gate,
		double normalGate, double floor);
};
}  // namespace whiskermap::smooth
