#pragma once
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/Wall.h>
#include <whiskermap/obs/Shapelet.h>

#include <array>
#include <cstdint>
#include <optional>

namespace whiskermap::model
{
/** The contacts a wall explains, folded into constant-memory sufficient statistics
 *  (doc/model.md, "Walls"): per long face (indexed against the reference normal: the first
 *  fold's face +1) the moments of the contacts' positions about an anchor (w, sum x, sum y,
 *  sum xx, sum xy, sum yy, weighted by 1/sigma_r^2), the moments of their normals' errors
 *  against the reference face normals (1/sigma_theta^2), their texture (1/sigma_tau^2) and
 *  the extent: the two contacts furthest along the reference direction. For a wall at any
 *  pose, sum_i Delta_WS (eq. 22) over the folded contacts is then a quadratic in its
 *  centre-line offset, yaw and texture: eq. 22 exactly while every contact lies within the
 *  extent (the extent covers them) and the wall turned by less than 90 degrees; eq. 12's null
 *  cause is dropped as for legs (LegEvidence). Scored isotropically (no shaft noise).
 *  A contact on an end cap joins the texture moments and the extent; its position and
 *  normal cost is frozen at its value when folded (a sum), so it does not pull the wall's
 *  yaw or offset (a first contact on a cap takes face +1's normal as the reference). */
class WallEvidence
{
   public:
	/** Folds contact `s` on its best face (eq. 22) of wall `w`, weighted by p's sigmas. */
	void add(const obs::Shapelet& s, const Wall& w, const ModelParams& p) { add(s, w, w.frame(), p); }
	/** The same with the wall's frame (Wall::frame(), Blackboard::wallFrame()). */
	void add(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p);
	/** sum_i log p(S_i | W) over the folded contacts (eq. 22). */
	double logLikelihood(const Wall& w, const ModelParams& p) const { return logLikelihood(w, w.frame(), p); }
	/** The same with the wall's frame (Wall::frame(), Blackboard::wallFrame()). */
	double logLikelihood(const Wall& w, const Wall::Frame& fr, const ModelParams& p) const;
	/** The wall of thickness `thickness` minimising the folded contacts' sum of Delta_WS (eq. 22)
	 *  over yaw and centre-line offset (closed form in the offset, golden section in the yaw,
	 *  within 0.5 rad of the mean normal), its texture their weighted mean and its extent from
	 *  the first to the last contact along it. Needs count() >= 1. With an `axis` (radians;
	 *  ModelParams::wallAxis, Manhattan walls) the yaw is the direction along the axis or at
	 *  right angles to it nearest that optimum (searched for only when the search's window
	 *  reaches past halfway between two such directions), and the offset the closed form at it. */
	Wall fit(double thickness, std::optional<double> axis = std::nullopt) const;

	uint32_t count() const { return m_count; }
	bool empty() const { return m_count == 0; }

	/** Raw statistics (serialization): STATS numbers and the count. */
	static constexpr size_t STATS = 2 * 6 + 3 + 3 + 3 + 4 + 1;
	/** STATS of map streams before version 10 (no end caps: the frozen cap cost is 0). */
	static constexpr size_t STATS_BEFORE_CAPS = STATS - 1;
	std::array<double, STATS> stats() const;
	static WallEvidence fromStats(const std::array<double, STATS>& v, uint32_t count);
	bool operator==(const WallEvidence& o) const { return stats() == o.stats() && m_count == o.m_count; }

   private:
	struct Face
	{
		double w = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
	};
	/** The unit normal at angle refNormal + d (computed once per d for the two below). */
	struct Normal
	{
		double x, y;
	};
	Normal normalAt(double d) const;
	/** The yaw offset in [lo, hi] minimising cost() at its best offset (golden section). */
	double freeYaw(double lo, double hi, double thickness) const;
	/** Position cost (sum across^2 / sigma_r^2) and angle cost of the folded contacts for a wall
	 *  whose face +1 (reference side) has normal n = normalAt(d) and whose centre line passes
	 *  at offset c from the anchor along that normal. */
	double cost(double d, const Normal& n, double c, double thickness) const;
	/** The offset c minimising cost() at the normal n. */
	double bestOffset(const Normal& n, double thickness) const;

	double m_ax = 0, m_ay = 0, m_phi = 0;  ///< anchor point and reference normal (face index 0)
	std::array<Face, 2> m_face{};  ///< 0: the reference face, 1: the opposite one
	double m_wa = 0, m_sa = 0, m_saa = 0;  ///< normal error vs the reference face normals
	double m_wt = 0, m_st = 0, m_stt = 0;  ///< texture
	double m_lox = 0, m_loy = 0, m_hix = 0, m_hiy = 0;  ///< first and last contact along the reference direction
	double m_capCost = 0;  ///< sum of eq. 22's position and normal cost of the end caps' contacts, as folded
	uint32_t m_count = 0;
};
}  // namespace whiskermap::model
