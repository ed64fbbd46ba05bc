#pragma once
#include <whiskermap/model/CowVector.h>
#include <whiskermap/model/Id.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace whiskermap::model
{
/** Points (ids) on a uniform grid of square cells kept in a hash map that grows with the
 *  number of cells ever occupied (a cell emptied stays, empty): for maps of any size (the
 *  lasting map's store), where SpatialHash's fixed buckets suit small, often reset
 *  blackboards. Cell indices are 64-bit and clamped. Copies share the hash map until one of
 *  them opens a new cell, and the cells' contents by chunks (CowVector). */
class SpatialGrid
{
   public:
	explicit SpatialGrid(double cellSize);

	void clear() { m_index.reset(), m_cells.clear(); }
	void insert(Id id, double x, double y);
	void erase(Id id, double x, double y);
	/** `id` moves from (x0, y0) to (x1, y1): written only when it changes cell. */
	void move(Id id, double x0, double y0, double x1, double y1);

	/** Chunks of cells (and the hash map, as one) this grid shares with a copy, and all of them. */
	size_t sharedChunks() const { return m_cells.sharedChunks() + (m_index.use_count() > 1); }
	size_t chunkCount() const { return m_cells.chunkCount() + (m_index != nullptr); }

	/** Calls f(id) for every id in a cell touching the square of half-side `radius` around
	 *  (x, y): a superset of the points within `radius`, each id once. */
	template <class F>
	void forEachNear(double x, double y, double radius, F&& f) const
	{
		const int64_t x0 = cell(x - radius), x1 = cell(x + radius), y0 = cell(y - radius), y1 = cell(y + radius);
		for (int64_t ix = x0; ix <= x1; ix++)
			for (int64_t iy = y0; iy <= y1; iy++)
				if (const uint32_t* c = find(Key{ix, iy}))
					for (const Id id : m_cells[*c]) f(id);
	}

   private:
	struct Key
	{
		int64_t ix, iy;
		bool operator==(const Key& o) const { return ix == o.ix && iy == o.iy; }
	};
	struct KeyHash
	{
		size_t operator()(const Key& k) const
		{
			return static_cast<size_t>(static_cast<uint64_t>(k.ix) * 0x9E3779B97F4A7C15ull ^
									   static_cast<uint64_t>(k.iy) * 0xC2B2AE3D27D4EB4Full);
		}
	};
	/** Clamped to +-2^62 (as SpatialHash): any finite coordinate has a cell, loops end. */
	int64_t cell(double v) const
	{
		constexpr double LIM = 4.611686018427387904e18;  // 2^62
		return static_cast<int64_t>(std::clamp(std::floor(v / m_cellSize), -LIM, LIM));
	}

	using Index = std::unordered_map<Key, uint32_t, KeyHash>;  ///< cell -> its slot in m_cells
	const uint32_t* find(const Key& k) const
	{
		if (!m_index) return nullptr;
		const auto it = m_index->find(k);
		return it == m_index->end() ? nullptr : &it->second;
	}

	double m_cellSize;
	std::shared_ptr<Index> m_index;  ///< null while empty; shared by copies until one opens a cell
	CowVector<std::vector<Id>> m_cells;
};
}  // namespace whiskermap::model
