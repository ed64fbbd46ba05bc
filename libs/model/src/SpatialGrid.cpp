#include <whiskermap/core/Error.h>
#include <whiskermap/model/SpatialGrid.h>

#include <algorithm>

namespace whiskermap::model
{
SpatialGrid::SpatialGrid(double cellSize) : m_cellSize(cellSize)
{
	if (!(cellSize > 0)) throw core::Error("SpatialGrid: the cell size must be positive");
}

void SpatialGrid::insert(Id id, double x, double y) { m_cells[Key{cell(x), cell(y)}].push_back(id); }

void SpatialGrid::erase(Id id, double x, double y)
{
	const auto it = m_cells.find(Key{cell(x), cell(y)});
	if (it == m_cells.end()) return;
	auto& v = it->second;
	v.erase(std::remove(v.begin(), v.end(), id), v.end());
	if (v.empty()) m_cells.erase(it);
}
}  // namespace whiskermap::model
