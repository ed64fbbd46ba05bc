#include <whiskermap/core/Error.h>
#include <whiskermap/inference/ShapeletMemory.h>

namespace whiskermap::inference
{
ShapeletMemory::ShapeletMemory(size_t capacity) : m_capacity(capacity)
{
	if (capacity == 0) throw core::Error("ShapeletMemory: capacity must be at least 1");
	m_items.reserve(capacity + 1);
}

void ShapeletMemory::add(const obs::Shapelet& s)
{
	m_items.push_back(s);
	if (m_items.size() > m_capacity) m_items.erase(m_items.begin());
}

void ShapeletMemory::add(const std::vector<obs::Shapelet>& shapelets)
{
	for (const auto& s : shapelets) add(s);
}
}  // namespace whiskermap::inference
