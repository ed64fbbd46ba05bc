#pragma once
#include <whiskermap/obs/SweptSector.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace whiskermap::model
{
/** Where a map has been explored: a coarse square grid (cell edge `cellSize()`, metres) that
 *  counts, per cell, the sweeps whose whiskers passed through it without touching anything
 *  there (`passes`: free space) and the sweeps that touched something in it (`touches`).
 *  Memory is bounded by the explored area, not by the number of sweeps: counts saturate at
 *  65535, and cells live in 16 x 16 chunks allocated only where a sweep reached, over the
 *  bounding box of the explored chunks. Copies share the chunks (copy-on-write): a copy costs
 *  one pointer per chunk, and only a chunk a later sweep changes is duplicated.
 *  doc/model.md, "Free space" and "The swept grid". */
class SweptGrid
{
   public:
	struct Cell
	{
		uint16_t passes = 0;  ///< sweeps whose shafts crossed the cell without touching there
		uint16_t touches = 0;  ///< sweeps with a contact in the cell
		bool explored() const { return passes > 0 || touches > 0; }
	};
	/** One explored cell, by its integer indices (floor(x / cellSize()), floor(y / cellSize())). */
	struct IndexedCell
	{
		int32_t ix = 0, iy = 0;
		Cell cell;
	};
	static constexpr int32_t CHUNK = 16;

	explicit SweptGrid(double cellSize = 0.1);

	double cellSize() const { return m_cell; }
	bool empty() const { return m_chunks.empty(); }
	/** Forgets everything; the cell edge becomes `cellSize` (metres, > 0). */
	void clear(double cellSize);

	/** One sweep: every cell a sector's shaft crossed gets a pass, every cell holding one of
	 *  `contacts` (world x, y) a touch instead, and the robot's own cell (robotX, robotY) a
	 *  pass (the robot stood there); each cell counts at most once per sweep. */
	void addSweep(
		double robotX, double robotY, const std::vector<obs::SweptSector>& sectors,
		const std::vector<std::array<double, 2>>& contacts);

	/** The cell holding the point (an unexplored cell when none). */
	Cell at(double x, double y) const;
	int32_t index(double v) const;
	Cell atIndex(int32_t ix, int32_t iy) const;

	/** Every explored cell (for serialization), by chunk then row. */
	std::vector<IndexedCell> cells() const;
	/** Sets one cell (for deserialization). */
	void set(int32_t ix, int32_t iy, Cell c);
	size_t chunkCount() const;
	/** Chunks this grid shares with a copy (use_count > 1). */
	size_t sharedChunks() const;

   private:
	using Chunk = std::array<Cell, CHUNK * CHUNK>;
	double m_cell;
	int32_t m_cx0 = 0, m_cy0 = 0, m_w = 0, m_h = 0;  ///< chunk bounding box
	std::vector<std::shared_ptr<Chunk>> m_chunks;  ///< m_w x m_h, row-major; null: unexplored

	/** The cell, its chunk allocated (growing the box) or unshared first. */
	Cell& writable(int32_t ix, int32_t iy);
	void grow(int32_t cx, int32_t cy);
};
}  // namespace whiskermap::model
