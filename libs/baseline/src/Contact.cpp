#include <whiskermap/baseline/Contact.h>

#include <cmath>

namespace whiskermap::baseline
{
std::vector<Contact> Contact::of(const obs::RawlogReader::Sweep& sweep, uint32_t index)
{
	const auto& o = *sweep.obs;
	const double sensorYaw = (mrpt::poses::CPose3D(sweep.robotPose) + o.sensorPose).yaw();
	std::vector<Contact> out;
	for (const auto& s : o.toShapelets(sweep.robotPose))
	{
		Contact c;
		c.p = {s.x, s.y};
		c.normal = s.normal;
		c.texture = s.texture;
		const double a = sensorYaw + o.whiskers[s.whisker].angle;
		c.shaft = {std::cos(a), std::sin(a)};
		c.sigma_r = o.noise.sigma_r, c.sigma_phi = o.noise.sigma_phi, c.sigma_tau = o.noise.sigma_tau;
		c.sweep = index;
		out.push_back(c);
	}
	return out;
}
}  // namespace whiskermap::baseline
