#include <whiskermap/baseline/FreeSpace.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::baseline
{
FreeSpace::Cell FreeSpace::cell(const Eigen::Vector2d& p) const
{
	return {long(std::floor(p.x() / m_cell)), long(std::floor(p.y() / m_cell))};
}

FreeSpace::FreeSpace(const std::vector<obs::RawlogReader::Sweep>& sweeps)
{
	for (const auto& s : sweeps)
	{
		const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(s.robotPose) + s.obs->sensorPose;
		for (const auto& w : s.obs->whiskers)
		{
			const double stop = w.touched ? w.angle : w.sweep_end;
			if (stop == w.sweep_start) continue;
			double px, py, pz;
			sensor.composePoint(w.mount_x, w.mount_y, 0, px, py, pz);
			// Counter-clockwise from the smaller angle.
			const double lo = sensor.yaw() + std::min(w.sweep_start, stop);
			m_sectors.push_back(Sector{{px, py}, w.length, lo, std::abs(stop - w.sweep_start)});
			const Eigen::Vector2d ext(w.length, w.length);
			const auto [x0, y0] = cell(Eigen::Vector2d(px, py) - ext);
			const auto [x1, y1] = cell(Eigen::Vector2d(px, py) + ext);
			for (long cx = x0; cx <= x1; cx++)
				for (long cy = y0; cy <= y1; cy++) m_grid[{cx, cy}].push_back(m_sectors.size() - 1);
		}
	}
}

double FreeSpace::depth(const Eigen::Vector2d& p) const
{
	const auto it = m_grid.find(cell(p));
	if (it == m_grid.end()) return 0;
	double deepest = 0;
	for (size_t k : it->second)
	{
		const auto& s = m_sectors[k];
		const Eigen::Vector2d d = p - s.pivot;
		const double rho = d.norm();
		if (rho >= s.radius || rho == 0) continue;
		double a = std::atan2(d.y(), d.x()) - s.from;
		a -= 2 * M_PI * std::floor(a / (2 * M_PI));  // in [0, 2 pi)
		if (a > s.span) continue;
		// Distance to the two bounding rays (the perpendicular one, or the pivot beyond 90 deg).
		auto toRay = [&](double angle) { return angle >= M_PI / 2 ? rho : rho * std::sin(angle); };
		deepest = std::max(deepest, std::min({s.radius - rho, toRay(a), toRay(s.span - a)}));
	}
	return deepest;
}
}  // namespace whiskermap::baseline
