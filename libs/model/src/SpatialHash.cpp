#include <whiskermap/core/Error.h>
#include <whiskermap/model/SpatialHash.h>

namespace whiskermap::model
{
SpatialHash::SpatialHash(double cellSize, size_t buckets) : m_cellSize(cellSize), m_head(buckets, -1)
{
	if (!(cellSize > 0) || buckets == 0)
		throw core::Error("SpatialHash: cell size and bucket count must be positive");
}

void SpatialHash::clear()
{
	std::fill(m_head.begin(), m_head.end(), -1);
	m_nodes.clear();
	m_free = -1;
}

void SpatialHash::insert(Id id, double x, double y)
{
	const int64_t ix = cell(x), iy = cell(y);
	int32_t n = m_free;
	if (n >= 0)
		m_free = m_nodes[static_cast<size_t>(n)].next;
	else
	{
		n = static_cast<int32_t>(m_nodes.size());
		m_nodes.emplace_back();
	}
	int32_t& head = m_head[bucket(ix, iy)];
	m_nodes[static_cast<size_t>(n)] = {ix, iy, id, head};
	head = n;
}

void SpatialHash::erase(Id id, double x, double y)
{
	const int64_t ix = cell(x), iy = cell(y);
	for (int32_t* link = &m_head[bucket(ix, iy)]; *link >= 0; link = &m_nodes[static_cast<size_t>(*link)].next)
	{
		Node& e = m_nodes[static_cast<size_t>(*link)];
		if (e.id != id || e.ix != ix || e.iy != iy) continue;
		const int32_t n = *link;
		*link = e.next;
		e.next = m_free;
		m_free = n;
		return;
	}
}
}  // namespace whiskermap::model
