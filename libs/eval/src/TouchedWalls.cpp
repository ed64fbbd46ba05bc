#include <whiskermap/eval/TouchedWalls.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::eval
{
TouchedWalls::TouchedWalls(std::vector<world::Wall> walls, double contactGate, double spread)
	: m_walls(std::move(walls)), m_gate(contactGate), m_spread(spread), m_touched(m_walls.size())
{
}

void TouchedWalls::add(const obs::RawlogReader::Sweep& sweep)
{
	for (const auto& s : sweep.obs->toShapelets(sweep.robotPose)) addContact(s.x, s.y);
}

void TouchedWalls::addContact(double x, double y)
{
	for (size_t i = 0; i < m_walls.size(); i++)
	{
		const auto& w = m_walls[i];
		const double L = w.length(), ux = (w.x1 - w.x0) / L, uy = (w.y1 - w.y0) / L;
		const double t = (x - w.x0) * ux + (y - w.y0) * uy;  // along the centre line
		const double across = std::abs(-(x - w.x0) * uy + (y - w.y0) * ux) - w.thickness / 2;
		if (t < -m_gate || t > L + m_gate || across > m_gate) continue;
		const double lo = std::max(0.0, t - m_spread), hi = std::min(L, t + m_spread);
		if (lo < hi) WallEvaluation::unite(m_touched[i], lo, hi);
	}
}
}  // namespace whiskermap::eval
