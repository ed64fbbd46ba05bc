#pragma once
#include <whiskermap/model/Factors.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/OrientedRect.h>
#include <whiskermap/model/Table.h>
#include <whiskermap/model/Wall.h>
#include <whiskermap/obs/SweptSector.h>

#include <vector>

namespace whiskermap::model
{
/** The free space of one inference problem: the sectors the whiskers of its sweeps swept
 *  without touching anything (obs::SweptSector), and the negative-evidence factor they put
 *  on every solid hypothesis (eq. 21, ours; doc/model.md, "Free space"). A leg, or the leg a
 *  table implies at an empty corner, that reaches into a swept sector by d metres costs
 *  log(p_miss + (1 - p_miss) exp(-d^2 / sigma_r^2)) per sector. */
class SweptSpace
{
   public:
	/** Holds `sectors` (replacing any); keeps capacity. */
	void assign(const std::vector<obs::SweptSector>& sectors) { m_sectors.assign(sectors.begin(), sectors.end()); }
	void clear() { m_sectors.clear(); }
	const std::vector<obs::SweptSector>& sectors() const { return m_sectors; }

	/** How deep rectangle `r` reaches into sector `s`, metres: the largest SweptSector::depth
	 *  over its corners, edge midpoints, centre and its point nearest the pivot (exact when
	 *  one piece of the sector's boundary is the nearest to all of the rectangle's deepest
	 *  part, the usual case for a leg small against a whisker); 0 when it stays out. */
	static double penetration(const obs::SweptSector& s, const OrientedRect& r);

	/** log phi_f of a solid rectangle (eq. 21): the sum over the sectors; 0 when the model's
	 *  free_space is off. */
	double logFactor(const OrientedRect& r, const ModelParams& p) const;

	/** How deep segment (ax, ay)-(bx, by) reaches into sector `s`, metres: the largest
	 *  SweptSector::depth along it. A sector of span <= pi is convex, so the segment's part
	 *  inside it is one interval (found exactly) along which the depth is concave: its
	 *  maximum by golden section. For a wider sector, a lower bound from 64 points. */
	static double segmentPenetration(const obs::SweptSector& s, double ax, double ay, double bx, double by);

	/** Eq. 21 for a wall (the per-pose mode; the lasting map's walls pay eq. 25 instead): its
	 *  slab's depth in each sector taken as the deepest of its centre line and its two long
	 *  faces (a lower bound within a quarter of its thickness); 0 when free_space is off. */
	double logWallFactor(const Wall& w, const ModelParams& p) const;

	/** Eq. 21 for the legs table `t` implies at its empty corners (counts[c] == 0): a square
	 *  leg of the table's leg width and yaw centred on each such corner. */
	double logEmptyCorners(const Table& t, const CornerCounts& counts, const ModelParams& p) const;

   private:
	std::vector<obs::SweptSector> m_sectors;
};
}  // namespace whiskermap::model
