#pragma once
#include <whiskermap/baseline/Contact.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace handmade
{
using whiskermap::baseline::Contact;

/** Noiseless contacts on the faces of a square leg (side w) at `centre`, `yaw`: `perFace`
 *  points spread along each face listed in `faces` (face k: outward normal yaw + k pi/2),
 *  each touched by a shaft coming in at 30 degrees to the normal. */
inline std::vector<Contact> leg(
	const Eigen::Vector2d& centre, double yaw, std::vector<int> faces = {0, 1, 2, 3}, int perFace = 5,
	double w = 0.05, double texture = 0.7)
{
	std::vector<Contact> out;
	for (int k : faces)
	{
		const double a = yaw + k * M_PI / 2;
		const Eigen::Vector2d n(std::cos(a), std::sin(a)), t(-n.y(), n.x());
		for (int i = 0; i < perFace; i++)
		{
			Contact c;
			const double s = perFace == 1 ? 0 : -w / 2 + w * i / (perFace - 1);
			c.p = centre + w / 2 * n + s * t;
			c.normal = std::atan2(n.y(), n.x());
			c.texture = texture;
			c.shaft = Eigen::Rotation2Dd(M_PI + (i % 2 ? 0.5 : -0.5)) * n;
			out.push_back(c);
		}
	}
	return out;
}

/** The four legs of a table of the known size (1.0 x 0.6 m); `legs` lists which corners. */
inline std::vector<Contact> table(
	const Eigen::Vector2d& centre, double yaw, std::vector<int> legs = {0, 1, 2, 3})
{
	std::vector<Contact> out;
	for (int k : legs)
	{
		const double sx = (k == 0 || k == 3) ? 1 : -1, sy = k < 2 ? 1 : -1;
		const auto c = leg(centre + Eigen::Rotation2Dd(yaw) * Eigen::Vector2d(sx * 0.5, sy * 0.3), yaw);
		out.insert(out.end(), c.begin(), c.end());
	}
	return out;
}
}  // namespace handmade
