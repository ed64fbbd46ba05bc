#pragma once
#include <whiskermap/model/Id.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace whiskermap::model
{
/** Uniform-grid spatial hash of points (hypothesis centres): cells of a fixed size hashed
 *  into a fixed number of buckets. Buckets keep their capacity across clear(), so after
 *  warm-up inserts and queries do not allocate. Answers any radius without duplicates. */
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
				for (const Entry& e : m_buckets[bucket(ix, iy)])
					if (e.ix == ix && e.iy == iy) f(e.id);
	}

   private:
	struct Entry
	{
		int64_t ix, iy;
		Id id;
	};
	/** 64-bit cell index, clamped to +-2^62 so that any finite coordinate has a cell and
	 *  the query loops above always end (indices and their +1 never overflow). */
	int64_t cell(double v) const
	{
		constexpr double LIM = 4.611686018427387904e18;  // 2^62
		return static_cast<int64_t>(std::clamp(std::floor(v / m_cellSize), -LIM, LIM));
	}
	size_t bucket(int64_t ix, int64_t iy) const;

	double m_cellSize;
	std::vector<std::vector<Entry>> m_buckets;
};
}  // namespace whiskermap::model
