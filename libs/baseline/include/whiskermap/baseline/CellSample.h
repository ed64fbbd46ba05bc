#pragma once
#include <whiskermap/core/SeedStream.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace whiskermap::baseline
{
/** A bounded sample of items placed in the plane: per square cell at most `cap` of them, a
 *  uniform sample (reservoir sampling, Vitter's algorithm R) of all the cell received. Memory
 *  is bounded by the area covered, not by how often it was covered: a log that drives the
 *  same path a thousand times keeps as much as one that drives it a few times
 *  (doc/baseline.md, "Bounded memory"). While no cell has received more than `cap` items,
 *  items() is every item added, in order. The choice is a hash of each item's arrival
 *  number, so the same input gives the same sample. */
template <class T>
class CellSample
{
   public:
	/** `cell`: edge in metres (> 0); `cap`: items kept per cell (> 0). Coordinates must be
	 *  finite and within RawlogScanner::MAX_COORDINATE (the reader's bound). */
	CellSample(double cell, size_t cap) : m_cell(cell), m_cap(cap) {}

	void add(double x, double y, const T& item)
	{
		Cell& c = m_cells[{long(std::floor(x / m_cell)), long(std::floor(y / m_cell))}];
		const uint64_t order = m_seen++;
		if (c.slots.size() < m_cap)
			c.slots.push_back({order, item});
		else
		{
			const uint64_t j = draw(order) % (c.seen + 1);  // keep the (seen+1)-th with probability cap/(seen+1)
			if (j < m_cap) c.slots[j] = {order, item};
		}
		c.seen++;
	}

	/** The items kept, in the order they were added. */
	std::vector<T> items() const
	{
		std::vector<const Slot*> kept;
		for (const auto& [key, c] : m_cells)
			for (const Slot& s : c.slots) kept.push_back(&s);
		std::sort(kept.begin(), kept.end(), [](const Slot* a, const Slot* b) { return a->order < b->order; });
		std::vector<T> out;
		out.reserve(kept.size());
		for (const Slot* s : kept) out.push_back(s->item);
		return out;
	}

	uint64_t seen() const { return m_seen; }  ///< items added
	size_t cells() const { return m_cells.size(); }

   private:
	struct Slot
	{
		uint64_t order;
		T item;
	};
	struct Cell
	{
		uint64_t seen = 0;
		std::vector<Slot> slots;
	};
	static uint64_t draw(uint64_t order)
	{
		return uint64_t(core::seedStream(order, 1)) << 32 | core::seedStream(order, 2);
	}

	double m_cell;
	size_t m_cap;
	uint64_t m_seen = 0;
	std::map<std::pair<long, long>, Cell> m_cells;
};
}  // namespace whiskermap::baseline
