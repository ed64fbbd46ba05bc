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
		for (const obs::SweptSector& sector : s.obs->toSweptSectors(s.robotPose))
		{
			m_sectors.push_back(sector);
			const Eigen::Vector2d pivot(sector.x, sector.y), ext(sector.radius, sector.radius);
			const auto [x0, y0] = cell(pivot - ext);
			const auto [x1, y1] = cell(pivot + ext);
			for (long cx = x0; cx <= x1; cx++)
				for (long cy = y0; cy <= y1; cy++) m_grid[{cx, cy}].push_back(m_sectors.size() - 1);
		}
}

double FreeSpace::depth(const Eigen::Vector2d& p) const
{
	const auto it = m_grid.find(cell(p));
	if (it == m_grid.end()) return 0;
	double deepest = 0;
	for (size_t k : it->second) deepest = std::max(deepest, m_sectors[k].depth(p.x(), p.y()));
	return deepest;
}
}  // namespace whiskermap::baseline
