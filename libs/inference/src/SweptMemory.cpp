#include <whiskermap/inference/SweptMemory.h>

namespace whiskermap::inference
{
void SweptMemory::add(size_t shapelets, const std::vector<obs::SweptSector>& sectors)
{
	m_sweeps.push_back({shapelets, sectors});
	// Walk back from the newest: an older sweep stays while it has a shapelet in memory.
	std::deque<Sweep> kept;
	size_t newer = 0;
	for (auto it = m_sweeps.rbegin(); it != m_sweeps.rend(); ++it)
	{
		const size_t n = it->shapelets;
		if (it == m_sweeps.rbegin() || (n > 0 && newer < m_capacity)) kept.push_front(std::move(*it));
		newer += n;
	}
	m_sweeps = std::move(kept);
	m_all.clear();
	for (const Sweep& s : m_sweeps) m_all.insert(m_all.end(), s.sectors.begin(), s.sectors.end());
}
}  // namespace whiskermap::inference
