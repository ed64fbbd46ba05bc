#include <whiskermap/eval/TouchedWalls.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::eval
{
TouchedWalls::TouchedWalls(const std::vector<world::Wall>& walls, double contactGate, double spread)
	: m_gate(contactGate), m_spread(spread), m_touched(walls.size())
{
	for (const auto& w : walls)
	{
		const double L = w.length();
		m_lines.push_back({w.x0, w.y0, (w.x1 - w.x0) / L, (w.y1 - w.y0) / L, L, w.thickness / 2});
	}
}

void TouchedWalls::add(const obs::RawlogReader::Sweep& sweep)
{
	for (const auto& s : sweep.obs->toShapelets(sweep.robotPose)) addContact(s.x, s.y);
}

void TouchedWalls::addContact(double x, double y)
{
	for (size_t i = 0; i < m_lines.size(); i++)
	{
		const Line& w = m_lines[i];
		const double t = (x - w.x0) * w.ux + (y - w.y0) * w.uy;  // along the centre line
		const double across = std::abs(-(x - w.x0) * w.uy + (y - w.y0) * w.ux) - w.halfThickness;
		if (t < -m_gate || t > w.length + m_gate || across > m_gate) continue;
		const double lo = std::max(0.0, t - m_spread), hi = std::min(w.length, t + m_spread);
		if (lo < hi) WallEvaluation::unite(m_touched[i], lo, hi);
	}
}
}  // namespace whiskermap::eval
