#pragma once
#include <whiskermap/obs/SweptSector.h>

#include <cstddef>
#include <deque>
#include <vector>

namespace whiskermap::inference
{
/** The free space that goes with the working memory (ShapeletMemory of the same capacity):
 *  the swept sectors (negative evidence, eq. 21) of the sweeps whose shapelets are still
 *  among the `capacity` most recent, plus those of the newest sweep. At most capacity + 1
 *  sweeps: bounded however long the robot sweeps empty space. */
class SweptMemory
{
   public:
	explicit SweptMemory(size_t capacity = 7) : m_capacity(capacity) {}

	/** One sweep, in order: its number of shapelets (added to the working memory) and its
	 *  swept sectors. */
	void add(size_t shapelets, const std::vector<obs::SweptSector>& sectors);
	void clear() { m_sweeps.clear(), m_all.clear(); }

	/** The kept sweeps' sectors, oldest sweep first. */
	const std::vector<obs::SweptSector>& sectors() const { return m_all; }
	size_t capacity() const { return m_capacity; }

   private:
	struct Sweep
	{
		size_t shapelets;
		std::vector<obs::SweptSector> sectors;
	};
	size_t m_capacity;
	std::deque<Sweep> m_sweeps;
	std::vector<obs::SweptSector> m_all;
};
}  // namespace whiskermap::inference
