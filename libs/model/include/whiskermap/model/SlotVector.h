#pragma once
#include <whiskermap/model/Id.h>

#include <cstdint>
#include <type_traits>
#include <vector>

namespace whiskermap::model
{
/** Items addressed by stable ids (indices). Removing frees the slot for a later add (last
 *  freed, first reused), so memory stays flat and ids of live items never change. `Items`
 *  holds them: a std::vector, or a CowVector whose copies share their chunks (then items are
 *  written through edit() only). */
template <class T, class Items = std::vector<T>>
class SlotVector
{
   public:
	Id add(const T& v)
	{
		Id id;
		if (m_free.empty())
		{
			id = static_cast<Id>(m_items.size());
			m_items.push_back(v);
			m_alive.push_back(1);
		}
		else
		{
			id = m_free.back();
			m_free.pop_back();
			edit(id) = v;
			m_alive[id] = 1;
		}
		++m_count;
		return id;
	}
	void remove(Id id)
	{
		m_alive[id] = 0;
		m_free.push_back(id);
		--m_count;
	}
	void clear()
	{
		m_items.clear();
		m_alive.clear();
		m_free.clear();
		m_count = 0;
	}
	bool alive(Id id) const { return id >= 0 && id < capacity() && m_alive[id]; }
	/** Ids are in [0, capacity()); test alive() before use. */
	Id capacity() const { return static_cast<Id>(m_items.size()); }
	size_t count() const { return m_count; }
	T& operator[](Id id) { return m_items[id]; }  ///< std::vector items only
	const T& operator[](Id id) const { return m_items[id]; }
	const Items& items() const { return m_items; }
	T& edit(Id id)
	{
		if constexpr (std::is_same_v<Items, std::vector<T>>)
			return m_items[id];
		else
			return m_items.edit(id);
	}

   private:
	Items m_items;
	std::vector<uint8_t> m_alive;
	std::vector<Id> m_free;
	size_t m_count = 0;
};
}  // namespace whiskermap::model
