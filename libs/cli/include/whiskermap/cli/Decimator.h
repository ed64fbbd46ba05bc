#pragma once
#include <cstddef>
#include <vector>

namespace whiskermap::cli
{
/** Keeps an evenly spread subset of a stream of unknown length in bounded memory: every
 *  item while there is room, then every 2nd, 4th, ... (items whose index is a multiple of
 *  the current stride). Deterministic. */
template <class T>
class Decimator
{
   public:
	explicit Decimator(size_t capacity) : m_capacity(capacity) {}

	void add(const T& item)
	{
		if (m_seen++ % m_stride != 0) return;
		m_items.push_back(item);
		if (m_items.size() < m_capacity) return;
		// Full: keep every other item and double the stride.
		size_t j = 0;
		for (size_t i = 0; i < m_items.size(); i += 2) m_items[j++] = m_items[i];
		m_items.resize(j);
		m_stride *= 2;
	}
	const std::vector<T>& items() const { return m_items; }
	size_t stride() const { return m_stride; }

   private:
	size_t m_capacity, m_stride = 1, m_seen = 0;
	std::vector<T> m_items;
};
}  // namespace whiskermap::cli
