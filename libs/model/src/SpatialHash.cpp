#include <whiskermap/core/Error.h>
#include <whiskermap/model/SpatialHash.h>

namespace whiskermap::model
{
SpatialHash::SpatialHash(double cellSize, size_t buckets) : m_cellSize(cellSize), m_buckets(buckets)
{
	if (!(cellSize > 0) || buckets == 0)
		throw core::Error("SpatialHash: cell size and bucket count must be positive");
}

void SpatialHash::clear()
{
	for (auto& b : m_buckets) b.clear();
}

size_t SpatialHash::bucket(int64_t ix, int64_t iy) const
{
	const uint64_t h = static_cast<uint64_t>(ix) * 73856093u ^ static_cast<uint64_t>(iy) * 19349663u;
	return static_cast<size_t>(h % m_buckets.size());
}

void SpatialHash::insert(Id id, double x, double y)
{
	const int64_t ix = cell(x), iy = cell(y);
	m_buckets[bucket(ix, iy)].push_back({ix, iy, id});
}

void SpatialHash::erase(Id id, double x, double y)
{
	auto& b = m_buckets[bucket(cell(x), cell(y))];
	for (auto& e : b)
		if (e.id == id)
		{
			e = b.back();
			b.pop_back();
			return;
		}
}
}  // namespace whiskermap::model
