#pragma once
#include <whiskermap/model/Id.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace whiskermap::model
{
/** Uniform-grid spatial hash of points (hypothesis centres): cells of a fixed size hashed
 *  into a fixed number of buckets, each bucket a chain of nodes in one flat array. A copy
 *  is three flat vectors, and after warm-up inserts, erases and queries do not allocate.
 *  Answers any radius without duplicates. For small, often copied boards; SpatialGrid suits
 *  maps of any size. */
class SpatialHash
{
   public:
	explicit SpatialHash(double cellSize, size_t buckets = 256);

	void clear();
	void insert(Id id, double x, double y);
	void erase(Id id, double x, double y);

	/** Calls f(id) for every id whose point lies in a cell touching the square of half-side
	 *  `radius` around (x, y): a superset of the points within `radius`, each id once. */
	template <class F>
	void forEachNear(double x, double y, double radius, F&& f) const
	{
		const int64_t x0 = cell(x - radius), x1 = cell(x + radius);
		const int64_t y0 = cell(y - radius), y1 = cell(y + radius);
		for (int64_t ix = x0; ix <= x1; ix++)
			for (int64_t iy = y0; iy <= y1; iy++)
				for (int32_t n = m_head[bucket(ix, iy)]; n >= 0; n = m_nodes[static_cast<size_t>(n)].next)
				{
					const Node& e = m_nodes[static_cast<size_t>(n)];
					if (e.ix == ix && e.iy == iy) f(e.id);
				}
	}

   private:
	struct Node
	{
		int64_t ix, iy;
		Id id;
		int32_t next;  ///< next node of the bucket (or of the free list), -1 at the end
	};
	/** 64-bit cell index, clamped to +-2^62 so that any finite coordinate has a cell and
	 *  the query loops above always end (indices and their +1 never overflow). */
	int64_t cell(double v) const
	{
		constexpr double LIM = 4.611686018427387904e18;  // 2^62
		return static_cast<int64_t>(std::clamp(std::floor(v / m_cellSize), -LIM, LIM));
	}
	size_t bucket(int64_t ix, int64_t iy) const
	{
		const uint64_t h = static_cast<uint64_t>(ix) * 0x9E3779B97F4A7C15ull ^ static_cast<uint64_t>(iy) * 0xC2B2AE3D27D4EB4Full;
		return static_cast<size_t>((h ^ (h >> 29)) % m_head.size());
	}

	double m_cellSize;
	std::vector<int32_t> m_head;  ///< first node per bucket, -1 if empty
	std::vector<Node> m_nodes;
	int32_t m_free = -1;  ///< first free node
};
}  // namespace whiskermap::model
