#pragma once
#include <whiskermap/obs/Shapelet.h>

#include <vector>

namespace whiskermap::inference
{
/** Working memory of the N most recent shapelets (paper section 5: N = 7); older ones are
 *  forgotten. Oldest first. */
class ShapeletMemory
{
   public:
	explicit ShapeletMemory(size_t capacity = 7);

	void add(const obs::Shapelet& s);
	void add(const std::vector<obs::Shapelet>& shapelets);  ///< in order: the last is newest
	void clear() { m_items.clear(); }

	const std::vector<obs::Shapelet>& shapelets() const { return m_items; }
	size_t capacity() const { return m_capacity; }

   private:
	size_t m_capacity;
	std::vector<obs::Shapelet> m_items;
};
}  // namespace whiskermap::inference
