#pragma once
#include <whiskermap/eval/WallEvaluation.h>
#include <whiskermap/obs/RawlogReader.h>

#include <vector>

namespace whiskermap::eval
{
/** The parts of the true walls the whiskers touched: what issue 11's wall recall is measured
 *  against ("the wall length the whiskers touched"; doc/evaluation.md). A contact is on a wall
 *  when its world-frame shapelet lies within `contactGate` of the wall's slab (its centre
 *  line +- thickness / 2; the arena's edges have none) and at most `contactGate` past its
 *  ends; it marks the centre line within `spread` of its projection as touched. Sweeps are
 *  given one at a time at the rawlog's poses (exact odometry: the true ones); memory is at
 *  most length / (2 spread) + 1 intervals per wall, however long the log. */
class TouchedWalls
{
   public:
	TouchedWalls(const std::vector<world::Wall>& walls, double contactGate, double spread);

	void add(const obs::RawlogReader::Sweep& sweep);
	void addContact(double x, double y);

	/** Per wall (the constructor's order), its touched parts, merged. */
	const std::vector<WallEvaluation::Intervals>& intervals() const { return m_touched; }

   private:
	/** A wall's centre line: its start, unit direction and length, and half its thickness. */
	struct Line
	{
		double x0, y0, ux, uy, length, halfThickness;
	};
	std::vector<Line> m_lines;
	double m_gate, m_spread;
	std::vector<WallEvaluation::Intervals> m_touched;
};
}  // namespace whiskermap::eval
