#pragma once
#include <whiskermap/model/Densities.h>
#include <whiskermap/obs/Shapelet.h>

#include <cmath>
#include <vector>

namespace whiskermap::test
{
/** Contacts generated from one known table: on `face` (0..3, outward normal theta + face *
 *  90 deg) of the leg at `corner`, `along` metres from the face centre. */
struct Touch
{
	int corner, face;
	double along;
};

inline std::vector<obs::Shapelet> touchTable(
	const model::Table& t, const model::ModelParams& p, const std::vector<Touch>& touches)
{
	std::vector<obs::Shapelet> out;
	for (const Touch& c : touches)
	{
		double lx = 0, ly = 0;
		model::tableCorner(t, c.corner, p, lx, ly);
		const double n = t.theta + c.face * M_PI_2;
		const double h = t.leg_width / 2;
		obs::Shapelet s;
		s.x = lx + h * std::cos(n) - c.along * std::sin(n);
		s.y = ly + h * std::sin(n) + c.along * std::cos(n);
		s.normal = std::atan2(std::sin(n), std::cos(n));
		s.texture = t.texture;
		s.whisker = static_cast<int>(out.size());
		out.push_back(s);
	}
	return out;
}
}  // namespace whiskermap::test
