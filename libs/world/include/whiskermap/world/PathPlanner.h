#pragma once
#include <Eigen/Core>
#include <whiskermap/world/World.h>

#include <vector>

namespace whiskermap::world
{
/** Where a round robot body may go in a world, on a grid of square cells, and the shortest
 *  ways between places (A* on the grid, then straightened). A cell is free when its centre is
 *  at least radius + clearance + half the cell's diagonal from every leg and wall, so every
 *  point of a free cell keeps the body `clearance` away from them; a segment counts as free
 *  when points every half cell along it lie in free cells, which keeps the body at least
 *  clearance - cell / 4 away (the distance to a solid changes no faster than position). The
 *  trajectory generators drive only along such segments. */
class PathPlanner
{
   public:
	/** Throws core::Error when the arena needs more than 2e7 cells. */
	PathPlanner(const World& world, double robotRadius, double clearance = 0.02, double cell = 0.025);

	/** True when `p` lies in a free cell. */
	bool free(const Eigen::Vector2d& p) const;
	/** True when the straight segment a-b is free (see above). */
	bool segmentFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
	/** True when `p` lies in a free cell of the largest connected free region. */
	bool inRegion(const Eigen::Vector2d& p) const;
	/** `p` itself if it lies in a free cell of the largest connected free region, else the
	 *  centre of the nearest such cell. Throws core::Error when no cell is free. */
	Eigen::Vector2d reachable(const Eigen::Vector2d& p) const;
	/** A shortest free polyline from a to b (both in the largest region: pass them through
	 *  reachable()), a first and b last; just {a, b} when the segment is free. */
	std::vector<Eigen::Vector2d> route(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
	/** The centre of free cell `i` of the largest region, i in [0, regionSize()). */
	Eigen::Vector2d regionCell(size_t i) const { return centre(m_region[i]); }
	size_t regionSize() const { return m_region.size(); }

   private:
	int cellOf(const Eigen::Vector2d& p) const;  ///< -1 outside the grid
	Eigen::Vector2d centre(int c) const;
	std::vector<int> astar(int from, int to) const;

	double m_x0, m_y0, m_cell;
	int m_nx, m_ny;
	std::vector<char> m_free;  ///< per cell
	std::vector<char> m_inRegion;  ///< per cell: in the largest connected free region
	std::vector<int> m_region;  ///< its cells
};
}  // namespace whiskermap::world
