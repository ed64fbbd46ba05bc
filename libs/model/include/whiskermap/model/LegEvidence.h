#pragma once
#include <whiskermap/model/Leg.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/obs/Shapelet.h>

#include <array>
#include <cstdint>

namespace whiskermap::model
{
/** The contacts a leg explains, folded into sufficient statistics: a lasting map keeps the
 *  evidence of every contact it ever explained in constant memory per leg (doc/model.md,
 *  "Folded evidence").
 *
 *  A folded contact keeps the face it lay on when folded (the leg face that explains it best
 *  in eq. 7's terms: distance to the face's line and normal against the face's normal) and
 *  the weights 1/sigma^2 of the model that scored it, its distance across the face weighted
 *  both ways: by 1/sigma_r^2 (the paper's eq. 7) and by 1/its variance under shaft noise
 *  (doc/model.md, "Shaft noise"); a score under a model uses the moments of its kind, so a
 *  map inferring with the paper's eq. 7 can still fit under shaft noise (the reported pose,
 *  doc/map-plugin.md). For the leg at any pose,
 *  the sum of Delta_LS (eq. 7) over the folded contacts is then a quadratic in the leg's
 *  centre, yaw and texture: r is the distance to the line of the contact's face, the angle
 *  error is the contact's normal against that face's normal. This equals eq. 7 while each
 *  contact projects onto its face and the leg turns by less than 45 degrees; eq. 12's null
 *  cause is dropped (log(p + c_S) ~ log p: the leg explains them by far). */
class LegEvidence
{
   public:
	/** Folds contact `s` of leg `l` (at its current pose), weighted by p's sigma_r,
	 *  sigma_theta and sigma_tau. */
	void add(const obs::Shapelet& s, const Leg& l, const ModelParams& p);
	/** Adds all of `o` (the contacts of a merged leg). */
	void merge(const LegEvidence& o);

	/** sum_i log p(S_i | L) over the folded contacts (eq. 7) for the leg at pose `l`. */
	double logLikelihood(const Leg& l, const ModelParams& p) const;

	/** The folded contacts' part of a leg fit: adds sum w u u^T to a (a11, a12, a22) and
	 *  sum w u (u.s - h) to b (b1, b2), u each face's outward normal for the leg at yaw
	 *  `theta` and h = w/2 for legs of side `side`, in units of 1/sigma_r^2 of `p`. */
	void addCentreEquations(
		double theta, double side, const ModelParams& p, double& a11, double& a12, double& a22, double& b1,
		double& b2) const;
	/** Weights of the folded contacts on the faces across the leg's x axis (faces 0, 2) and
	 *  across its y axis (1, 3), for the leg at yaw `theta`. */
	void axisWeights(double theta, double& x, double& y) const;
	/** Weighted mean yaw of the folded contacts (modulo 90 degrees, near the reference yaw)
	 *  and its weight in units of 1/sigma_theta^2 of `p`; weight 0 when empty. */
	double meanYaw(const ModelParams& p, double& weight) const;
	/** Weighted mean texture and its weight in units of 1/sigma_tau^2 of `p`. */
	double meanTexture(const ModelParams& p, double& weight) const;

	uint32_t count() const { return m_count; }
	bool empty() const { return m_count == 0; }

	/** Raw statistics, for serialization: 3 + 4 * 6 + 6 + 1 + 4 * 6 numbers and the count
	 *  (streams of map version 1 hold the first 33: no shaft-noise normaliser; version 2 the
	 *  first 34: one set of face moments, weighted as the model that folded them said). */
	static constexpr size_t STATS = 58;
	std::array<double, STATS> stats() const;
	/** From the first `known` numbers of `v` (older streams: 33 or 34); without the second
	 *  set of face moments, both sets are the first. */
	static LegEvidence fromStats(const std::array<double, STATS>& v, uint32_t count, size_t known = STATS);

	bool operator==(const LegEvidence& o) const { return stats() == o.stats() && m_count == o.m_count; }

   private:
	/** Moments of one face's contacts, relative to the anchor, weighted by 1/sigma_r^2. */
	struct Face
	{
		double w = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
	};
	/** Yaw offset of a leg at yaw `theta` from the reference, modulo 90 deg, and the index
	 *  shift n of its own faces: face k's normal is theta_ref + d + k pi/2 = theta + (k - n) pi/2. */
	void offset(double theta, double& d, int& n) const;

	double m_ax = 0, m_ay = 0, m_theta = 0;  ///< anchor point and reference yaw
	using Faces = std::array<Face, 4>;
	/** The face moments a score under `p` uses (shaft noise or the paper's eq. 7). */
	const Faces& faces(const ModelParams& p) const { return p.shaft_noise ? m_shaftFace : m_face; }

	Faces m_face{};  ///< by face index relative to the reference yaw, weights 1/sigma_r^2
	Faces m_shaftFace{};  ///< the same contacts weighted by 1/variance under shaft noise
	double m_wa = 0, m_sa = 0, m_saa = 0;  ///< normal error vs face normal at the reference yaw
	double m_wt = 0, m_st = 0, m_stt = 0;  ///< texture
	double m_norm = 0;  ///< sum of log(sigma_r / sigma across the face) (shaft noise only)
	uint32_t m_count = 0;
};
}  // namespace whiskermap::model
