#include <whiskermap/core/Error.h>
#include <whiskermap/model/SpatialGrid.h>

#include <algorithm>

namespace whiskermap::model
{
SpatialGrid::SpatialGrid(double cellSize) : m_cellSize(cellSize)
{
	if (!(cellSize > 0)) throw core::Error("SpatialGrid: the cell size must be positive");
}

void SpatialGrid::insert(Id id, double x, double y)
{
	const Key k{cell(x), cell(y)};
	if (const uint32_t* c = find(k)) return m_cells.edit(*c).push_back(id);
	if (!m_index)
		m_index = std::make_shared<Index>();
	else if (m_index.use_count() > 1)  // shared with a copy: copy on write
		m_index = std::make_shared<Index>(*m_index);
	m_index->emplace(k, static_cast<uint32_t>(m_cells.size()));
	m_cells.push_back({id});
}

void SpatialGrid::erase(Id id, double x, double y)
{
	const uint32_t* c = find(Key{cell(x), cell(y)});
	if (!c) return;
	auto& v = m_cells.edit(*c);
	v.erase(std::remove(v.begin(), v.end(), id), v.end());
}

void SpatialGrid::move(Id id, double x0, double y0, double x1, double y1)
{
	if (cell(x0) == cell(x1) && cell(y0) == cell(y1)) return;
	erase(id, x0, y0);
	insert(id, x1, y1);
}
}  // namespace whiskermap::model
