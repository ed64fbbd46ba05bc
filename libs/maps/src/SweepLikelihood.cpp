#include <whiskermap/core/Angles.h>
#include <whiskermap/maps/SweepLikelihood.h>
#include <whiskermap/world/WhiskerContact.h>

#include <cmath>

namespace whiskermap::maps
{
double SweepLikelihood::logLikelihood(
	const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& robotPose,
	const std::vector<world::Obstacle>& solids, const TOptions& o)
{
	const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(robotPose) + sweep.sensorPose;
	const double yaw = sensor.yaw();
	std::vector<world::Obstacle> near;
	double ll = 0;
	for (const auto& w : sweep.whiskers)
	{
		double px, py, pz;
		sensor.composePoint(w.mount_x, w.mount_y, 0, px, py, pz);
		const Eigen::Vector2d pivot(px, py);
		near.clear();
		for (const auto& s : solids)
			if ((s.corners[0] - pivot).norm() <= w.length + (s.corners[2] - s.corners[0]).norm())
				near.push_back(s);
		const auto predicted =
			world::WhiskerContact::first(pivot, w.length, yaw + w.sweep_start, yaw + w.sweep_end, near);
		if (w.touched && predicted)
		{
			const Eigen::Vector2d seen =
				pivot + w.r * Eigen::Vector2d(std::cos(yaw + w.angle), std::sin(yaw + w.angle));
			const double d2 = (seen - predicted->point).squaredNorm();
			const double a = core::wrapToPi(yaw + w.normal - predicted->normal);
			ll += std::log(
				(1 - o.p_unexplained) * std::exp(-d2 / (2 * o.sigma_contact * o.sigma_contact) -
												 a * a / (2 * o.sigma_normal * o.sigma_normal)) +
				o.p_unexplained);
		}
		else if (w.touched)
			ll += std::log(o.p_unexplained);
		else if (predicted)
			ll += std::log(o.p_miss);
	}
	return ll;
}
}  // namespace whiskermap::maps
