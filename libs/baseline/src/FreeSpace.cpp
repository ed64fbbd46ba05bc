#include <whiskermap/baseline/FreeSpace.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace whiskermap::baseline
{
FreeSpace::Cell FreeSpace::cell(const Eigen::Vector2d& p) const
{
	return {long(std::floor(p.x() / CELL)), long(std::floor(p.y() / CELL))};
}

FreeSpace::FreeSpace(std::vector<obs::SweptSector> sectors) : m_sectors(std::move(sectors))
{
	for (size_t k = 0; k < m_sectors.size(); k++)
	{
		const obs::SweptSector& sector = m_sectors[k];
		const Eigen::Vector2d pivot(sector.x, sector.y), ext(sector.radius, sector.radius);
		const auto [x0, y0] = cell(pivot - ext);
		const auto [x1, y1] = cell(pivot + ext);
		for (long cx = x0; cx <= x1; cx++)
			for (long cy = y0; cy <= y1; cy++) m_grid[{cx, cy}].push_back(k);
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
