#include <whiskermap/core/Angles.h>
#include <whiskermap/world/WhiskerContact.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <algorithm>

namespace whiskermap::world
{
WhiskerSimulator::WhiskerSimulator(
	World world, Robot robot, obs::TSensorNoise noise, uint64_t seed)
	: m_world(std::move(world)),
	  m_robot(std::move(robot)),
	  m_noise(noise),
	  m_obstacles(m_world.obstacles()),
	  m_rng(static_cast<uint32_t>(seed ^ (seed >> 32)))
{
}

bool WhiskerSimulator::poseIsFree(const mrpt::poses::CPose2D& pose) const
{
	const Eigen::Vector2d c(pose.x(), pose.y());
	return std::all_of(m_obstacles.begin(), m_obstacles.end(), [&](const Obstacle& o) {
		return o.distance(c) > m_robot.radius;
	});
}

obs::CObservationWhiskerContacts::Ptr WhiskerSimulator::sense(
	const mrpt::poses::CPose2D& pose, mrpt::Clock::time_point stamp, std::vector<Truth>* truth)
{
	auto o = m_robot.blankSweep(m_noise, stamp);
	if (truth) truth->assign(o->whiskers.size(), Truth{});

	// Work in the world frame: sensor frame = robot pose + sensor pose (planar).
	const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(pose) + m_robot.sensorPose;
	const double yaw = sensor.yaw();
	for (size_t i = 0; i < o->whiskers.size(); i++)
	{
		auto& w = o->whiskers[i];
		double px, py, pz;
		sensor.composePoint(w.mount_x, w.mount_y, 0, px, py, pz);
		const auto c = WhiskerContact::first(
			{px, py}, w.length, yaw + w.sweep_start, yaw + w.sweep_end, m_obstacles);
		if (!c) continue;
		w.touched = true;
		const Obstacle& hit = m_obstacles[c->obstacle];
		if (truth) (*truth)[i] = Truth{hit.table, hit.leg, hit.table < 0};
		// Reading noise (eqs. 1-3); clamped so a reading stays physically possible.
		w.angle = std::clamp(
			c->angle - yaw, std::min(w.sweep_start, w.sweep_end),
			std::max(w.sweep_start, w.sweep_end));
		w.r = std::clamp(c->r + m_rng.drawGaussian1D(0, m_noise.sigma_r), 0.0, w.length);
		w.normal = core::wrapToPi(c->normal - yaw + m_rng.drawGaussian1D(0, m_noise.sigma_phi));
		w.texture = std::clamp(hit.texture + m_rng.drawGaussian1D(0, m_noise.sigma_tau), 0.0, 1.0);
	}
	return o;
}
}  // namespace whiskermap::world
