#pragma once
#include <Eigen/Core>
#include <whiskermap/obs/SweptSector.h>

#include <map>
#include <vector>

namespace whiskermap::baseline
{
/** Negative evidence: the regions the whiskers swept without touching anything. In one whisk
 *  a whisker's shaft turns from its start angle to where it stopped (its contact, or the end
 *  of the sweep), so the circular sector it covered holds no obstacle (obs::SweptSector). The
 *  angles come from the actuator, not the noisy radial reading, so the sectors are exact. */
class FreeSpace
{
   public:
	/** Edge of the grid cells (metres) that index the sectors. */
	static constexpr double CELL = 0.5;

	explicit FreeSpace(std::vector<obs::SweptSector> sectors);

	/** How deep a point lies inside the swept region, metres: the largest, over the sectors
	 *  holding it, of its distance to the sector's boundary (0 when no sector holds it). A
	 *  square leg with half-diagonal d centred at `p` was swept through when this exceeds d. */
	double depth(const Eigen::Vector2d& p) const;

	size_t sectors() const { return m_sectors.size(); }

   private:
	using Cell = std::pair<long, long>;
	Cell cell(const Eigen::Vector2d& p) const;

	std::vector<obs::SweptSector> m_sectors;
	std::map<Cell, std::vector<size_t>> m_grid;  ///< sectors whose bounding box meets each cell
};
}  // namespace whiskermap::baseline
