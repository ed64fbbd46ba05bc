#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/LegEvidence.h>

#include <cmath>
#include <limits>
#include <utility>

namespace whiskermap::model
{
namespace
{
double sq(double v) { return v * v; }
/** Half-extent across leg l's own face j (0, 2: along its x axis; 1, 3: along y). */
double halfExtent(const Leg& l, int j) { return (((j % 4) + 4) % 2 == 0 ? l.wx : l.wy) / 2; }
template <class Face>
void addPoint(Face& f, double w, double ex, double ey)
{
	f.w += w, f.sx += w * ex, f.sy += w * ey;
	f.sxx += w * ex * ex, f.sxy += w * ex * ey, f.syy += w * ey * ey;
}
/** Adds face moments g, anchored (dx, dy) away, to f. */
template <class Face>
void addMoments(Face& f, const Face& g, double dx, double dy)
{
	f.w += g.w;
	f.sx += g.sx + g.w * dx, f.sy += g.sy + g.w * dy;
	f.sxx += g.sxx + 2 * g.sx * dx + g.w * dx * dx;
	f.sxy += g.sxy + g.sx * dy + g.sy * dx + g.w * dx * dy;
	f.syy += g.syy + 2 * g.sy * dy + g.w * dy * dy;
}
}  // namespace

void LegEvidence::offset(double theta, double& d, int& n) const
{
	d = core::angleDiff(theta, m_theta, M_PI_2);
	n = static_cast<int>(std::lround(core::angleDiff(theta - d, m_theta, 2 * M_PI) / M_PI_2));
}

void LegEvidence::add(const obs::Shapelet& s, const Leg& l, const ModelParams& p)
{
	if (m_count == 0) m_ax = l.x, m_ay = l.y, m_theta = l.theta;
	// The contact's face: the one of the leg that explains it best in eq. 7's own terms
	// (distance to the face's line and normal against the face's normal), indexed from the
	// reference yaw. Near a corner of a leg that is still a little off, the face nearest by
	// position alone can be the wrong one; the normal then tells.
	// With shaft noise (eq. 7's variance per face: contactVariance) each face weighs the
	// contact by its own 1/variance. Both kinds of moments are kept on the face chosen.
	const double wa = 1 / sq(p.sigma_theta), wt = 1 / sq(p.sigma_tau);
	double d = 0;
	int n = 0;
	offset(l.theta, d, n);
	int k = 0;
	double best = std::numeric_limits<double>::infinity();
	for (int f = 0; f < 4; f++)
	{
		const double a = m_theta + d + f * M_PI_2, ux = std::cos(a), uy = std::sin(a);
		const double r = ux * (s.x - l.x) + uy * (s.y - l.y) - halfExtent(l, f - n);
		const double w = 1 / contactVariance(s, ux, uy, p);
		const double norm = p.shaft_noise ? 0.5 * std::log(sq(p.sigma_r) * w) : 0;  // 1-D normaliser
		const double cost = w * r * r - norm + wa * sq(core::angleDiff(s.normal, a, 2 * M_PI));
		if (cost < best) best = cost, k = f;
	}
	const double normal = m_theta + d + k * M_PI_2;  // the chosen face's, for its shaft weight
	const double ws = 1 / shaftVariance(s, std::cos(normal), std::sin(normal), p);
	m_norm += 0.5 * std::log(sq(p.sigma_r) * ws);
	const double ex = s.x - m_ax, ey = s.y - m_ay;
	addPoint(m_face[k], 1 / sq(p.sigma_r), ex, ey);
	addPoint(m_shaftFace[k], ws, ex, ey);
	const double a = core::angleDiff(s.normal, m_theta + k * M_PI_2, 2 * M_PI);
	m_wa += wa, m_sa += wa * a, m_saa += wa * a * a;
	m_wt += wt, m_st += wt * s.texture, m_stt += wt * s.texture * s.texture;
	m_count++;
}

void LegEvidence::merge(const LegEvidence& o)
{
	if (o.m_count == 0) return;
	if (m_count == 0)
	{
		*this = o;
		return;
	}
	// o's face k is our face k + n; its angles shift by its reference's offset d.
	double d = 0;
	int n = 0;
	offset(o.m_theta, d, n);
	const double dx = o.m_ax - m_ax, dy = o.m_ay - m_ay;  // re-anchor o's moments
	for (int k = 0; k < 4; k++)
	{
		addMoments(m_face[((k + n) % 4 + 4) % 4], o.m_face[k], dx, dy);
		addMoments(m_shaftFace[((k + n) % 4 + 4) % 4], o.m_shaftFace[k], dx, dy);
	}
	m_wa += o.m_wa, m_sa += o.m_sa + o.m_wa * d, m_saa += o.m_saa + 2 * d * o.m_sa + o.m_wa * d * d;
	m_wt += o.m_wt, m_st += o.m_st, m_stt += o.m_stt;
	m_norm += o.m_norm;
	m_count += o.m_count;
}

double LegEvidence::logLikelihood(const Leg& l, const ModelParams& p) const
{
	if (m_count == 0) return 0;
	double d = 0;
	int n = 0;
	offset(l.theta, d, n);
	const double gx = l.x - m_ax, gy = l.y - m_ay;
	double delta = 0;
	// Face k's outward normal u turns by a quarter turn per face: (ux, uy) -> (-uy, ux).
	double ux = std::cos(m_theta + d), uy = std::sin(m_theta + d);
	const Faces& faces = this->faces(p);
	for (int k = 0; k < 4; k++, std::swap(ux, uy), ux = -ux)
	{
		const Face& f = faces[k];
		if (f.w == 0) continue;
		// sum w (u.e - t)^2 with t = u.g + h: the contacts' distances to the face line (eq. 7's r).
		const double t = ux * gx + uy * gy + halfExtent(l, k - n);
		delta += ux * ux * f.sxx + 2 * ux * uy * f.sxy + uy * uy * f.syy - 2 * t * (ux * f.sx + uy * f.sy) + f.w * t * t;
	}
	delta += m_saa - 2 * d * m_sa + m_wa * d * d;  // normal vs face normal
	delta += m_stt - 2 * l.texture * m_st + m_wt * l.texture * l.texture;  // texture
	return m_count * core::cachedLog(p.alpha_S) + (p.shaft_noise ? m_norm : 0) - delta;  // eq. 7 summed
}

void LegEvidence::addCentreEquations(
	double theta, double side, const ModelParams& p, double& a11, double& a12, double& a22, double& b1,
	double& b2) const
{
	double d = 0;
	int n = 0;
	offset(theta, d, n);
	const double scale = sq(p.sigma_r);  // weights in units of the model's 1/sigma_r^2
	double ux = std::cos(m_theta + d), uy = std::sin(m_theta + d);
	const Faces& faces = this->faces(p);
	for (int k = 0; k < 4; k++, std::swap(ux, uy), ux = -ux)
	{
		const Face& f = faces[k];
		if (f.w == 0) continue;
		const double w = f.w * scale;
		// world sum w u.s = u.(sum w e + w anchor)
		const double us = scale * (ux * (f.sx + f.w * m_ax) + uy * (f.sy + f.w * m_ay));
		a11 += w * ux * ux, a12 += w * ux * uy, a22 += w * uy * uy;
		b1 += ux * (us - w * side / 2), b2 += uy * (us - w * side / 2);
	}
}

void LegEvidence::axisWeights(double theta, double& x, double& y) const
{
	double d = 0;
	int n = 0;
	offset(theta, d, n);
	x = y = 0;
	for (int k = 0; k < 4; k++) (((k - n) % 2 + 2) % 2 == 0 ? x : y) += m_face[k].w;
}

double LegEvidence::meanYaw(const ModelParams& p, double& weight) const
{
	weight = m_wa * sq(p.sigma_theta);
	return m_wa > 0 ? m_theta + m_sa / m_wa : m_theta;
}

double LegEvidence::meanTexture(const ModelParams& p, double& weight) const
{
	weight = m_wt * sq(p.sigma_tau);
	return m_wt > 0 ? m_st / m_wt : 0;
}

std::array<double, LegEvidence::STATS> LegEvidence::stats() const
{
	std::array<double, STATS> v{};
	size_t i = 0;
	v[i++] = m_ax, v[i++] = m_ay, v[i++] = m_theta;
	for (const Face& f : m_face) v[i++] = f.w, v[i++] = f.sx, v[i++] = f.sy, v[i++] = f.sxx, v[i++] = f.sxy, v[i++] = f.syy;
	v[i++] = m_wa, v[i++] = m_sa, v[i++] = m_saa, v[i++] = m_wt, v[i++] = m_st, v[i++] = m_stt;
	v[i++] = m_norm;
	for (const Face& f : m_shaftFace) v[i++] = f.w, v[i++] = f.sx, v[i++] = f.sy, v[i++] = f.sxx, v[i++] = f.sxy, v[i++] = f.syy;
	return v;
}

LegEvidence LegEvidence::fromStats(const std::array<double, STATS>& v, uint32_t count, size_t known)
{
	LegEvidence e;
	size_t i = 0;
	e.m_ax = v[i++], e.m_ay = v[i++], e.m_theta = v[i++];
	for (Face& f : e.m_face) f.w = v[i++], f.sx = v[i++], f.sy = v[i++], f.sxx = v[i++], f.sxy = v[i++], f.syy = v[i++];
	e.m_wa = v[i++], e.m_sa = v[i++], e.m_saa = v[i++], e.m_wt = v[i++], e.m_st = v[i++], e.m_stt = v[i++];
	e.m_norm = v[i++];
	for (Face& f : e.m_shaftFace) f.w = v[i++], f.sx = v[i++], f.sy = v[i++], f.sxx = v[i++], f.sxy = v[i++], f.syy = v[i++];
	if (known < STATS) e.m_shaftFace = e.m_face;  // an older stream: one set, as folded
	e.m_count = count;
	return e;
}
}  // namespace whiskermap::model
