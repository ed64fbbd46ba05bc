#include <whiskermap/core/Angles.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/WallEvidence.h>

#include <cmath>

namespace whiskermap::model
{
namespace
{
double sq(double v) { return v * v; }
}  // namespace

void WallEvidence::add(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p)
{
	const int side = bestWallFace(s, w, fr, p);
	const bool cap = side == 2 || side == -2;
	// The first contact anchors the moments; the reference normal is its face's (face +1's when
	// it lies on an end cap).
	if (m_count == 0)
		m_ax = s.x, m_ay = s.y, m_phi = w.face(fr, s.x, s.y, cap ? 1 : side).normal, m_lox = m_hix = s.x, m_loy = m_hiy = s.y;
	const double qx = s.x - m_ax, qy = s.y - m_ay;
	if (cap)
	{
		// An end cap's contact: its position and normal cost (eq. 22, isotropic as every folded
		// contact) frozen as folded; its texture and extent below, as a long face's.
		const Wall::FaceHit h = w.hit(fr, s.x, s.y, side);
		m_capCost += (sq(h.across) + sq(h.excess)) / sq(p.sigma_r) + sq(core::wrapToPi(s.normal - h.normal) / p.sigma_theta);
	}
	else
	{
		// Face index against the reference normal: 0 when the face's normal is within 90 deg of it.
		const double faceNormal = w.face(fr, s.x, s.y, side).normal;
		const int k = std::cos(faceNormal - m_phi) >= 0 ? 0 : 1;
		const double wr = 1 / sq(p.sigma_r);
		Face& f = m_face[static_cast<size_t>(k)];
		f.w += wr, f.sx += wr * qx, f.sy += wr * qy, f.sxx += wr * qx * qx, f.sxy += wr * qx * qy, f.syy += wr * qy * qy;
		const double e = core::wrapToPi(s.normal - m_phi - k * M_PI), wa = 1 / sq(p.sigma_theta);
		m_wa += wa, m_sa += wa * e, m_saa += wa * e * e;
	}
	const double wt = 1 / sq(p.sigma_tau);
	m_wt += wt, m_st += wt * s.texture, m_stt += wt * s.texture * s.texture;
	// Extent along the reference direction u = (sin phi, -cos phi).
	const double ux = std::sin(m_phi), uy = -std::cos(m_phi), a = ux * qx + uy * qy;
	if (a < ux * (m_lox - m_ax) + uy * (m_loy - m_ay)) m_lox = s.x, m_loy = s.y;
	if (a > ux * (m_hix - m_ax) + uy * (m_hiy - m_ay)) m_hix = s.x, m_hiy = s.y;
	m_count++;
}

WallEvidence::Normal WallEvidence::normalAt(double d) const { return {std::cos(m_phi + d), std::sin(m_phi + d)}; }

double WallEvidence::cost(double d, const Normal& n, double c, double thickness) const
{
	const double nx = n.x, ny = n.y;
	double sum = m_saa - 2 * d * m_sa + m_wa * d * d;  // eq. 22's angle term
	for (int k = 0; k < 2; k++)
	{
		// Face k: outward normal sk n, line sk n . q = sk c + thickness / 2 (q about the anchor).
		const Face& f = m_face[static_cast<size_t>(k)];
		const double sk = k == 0 ? 1 : -1, h = sk * c + thickness / 2;
		const double nSn = nx * nx * f.sxx + 2 * nx * ny * f.sxy + ny * ny * f.syy, nm = nx * f.sx + ny * f.sy;
		sum += nSn - 2 * h * sk * nm + f.w * h * h;  // eq. 22's across term, summed
	}
	return sum;
}

double WallEvidence::bestOffset(const Normal& n, double thickness) const
{
	const double nx = n.x, ny = n.y;
	const Face &a = m_face[0], &b = m_face[1];
	const double w = a.w + b.w;
	if (w <= 0) return 0;
	return (nx * (a.sx + b.sx) + ny * (a.sy + b.sy) - thickness / 2 * (a.w - b.w)) / w;
}

double WallEvidence::logLikelihood(const Wall& w, const Wall::Frame& fr, const ModelParams& p) const
{
	if (m_count == 0) return 0;
	// The wall's face whose normal is within 90 deg of the reference one is face index 0.
	const Wall::FaceHit h = w.face(fr, m_ax, m_ay, 1);
	const int side = std::cos(h.normal - m_phi) >= 0 ? 1 : -1;
	const Wall::FaceHit hs = side == 1 ? h : w.face(fr, m_ax, m_ay, side);
	const double d = core::wrapToPi(hs.normal - m_phi);
	// Offset of the centre line from the anchor along the reference face's normal.
	const double c = -(hs.across + w.thickness / 2);
	const double tex = m_stt - 2 * w.texture * m_st + m_wt * w.texture * w.texture;
	// The weights were 1/sigma^2 of the folding model: the costs are eq. 22's Delta sums.
	return m_count * std::log(p.alpha_S) - cost(d, normalAt(d), c, w.thickness) - tex - m_capCost;  // eq. 22, summed
}

double WallEvidence::freeYaw(double lo, double hi, double thickness) const
{
	// Golden section over the yaw offset; the offset in closed form.
	const double g = (std::sqrt(5.0) - 1) / 2;
	const auto f = [&](double d) {
		const Normal n = normalAt(d);
		return cost(d, n, bestOffset(n, thickness), thickness);
	};
	double a = hi - g * (hi - lo), b = lo + g * (hi - lo), fa = f(a), fb = f(b);
	for (int i = 0; i < 60; i++)
	{
		if (fa < fb) hi = b, b = a, fb = fa, a = hi - g * (hi - lo), fa = f(a);
		else lo = a, a = b, fa = fb, b = lo + g * (hi - lo), fb = f(b);
	}
	return (lo + hi) / 2;
}

Wall WallEvidence::fit(double thickness, std::optional<double> axis) const
{
	// The free optimum lies within 0.5 rad of the mean normal error.
	const double mean = m_wa > 0 ? m_sa / m_wa : 0, lo = mean - 0.5, hi = mean + 0.5;
	double d = 0;
	if (axis)  // the face normal m_phi + d held to axis + k pi/2, the k nearest the free optimum
	{
		const auto nearest = [&](double v) { return std::round((m_phi + v - *axis) / M_PI_2); };
		// k is monotone in d: when both ends of the search's interval give the same k, so does
		// the optimum, which is then not searched for.
		const double kLo = nearest(lo), k = kLo == nearest(hi) ? kLo : nearest(freeYaw(lo, hi, thickness));
		d = *axis + k * M_PI_2 - m_phi;
	}
	else
		d = freeYaw(lo, hi, thickness);
	const Normal n = normalAt(d);
	const double c = bestOffset(n, thickness), nx = n.x, ny = n.y, ux = ny, uy = -nx;
	const double cx = m_ax + c * nx, cy = m_ay + c * ny;  // a point of the centre line
	const double a0 = ux * (m_lox - cx) + uy * (m_loy - cy), a1 = ux * (m_hix - cx) + uy * (m_hiy - cy);
	Wall w;
	w.x0 = cx + a0 * ux, w.y0 = cy + a0 * uy, w.x1 = cx + a1 * ux, w.y1 = cy + a1 * uy;
	w.thickness = thickness;
	w.texture = m_wt > 0 ? m_st / m_wt : 0;
	return w;
}

std::array<double, WallEvidence::STATS> WallEvidence::stats() const
{
	const Face &a = m_face[0], &b = m_face[1];
	return {m_ax, m_ay, m_phi, a.w, a.sx, a.sy, a.sxx, a.sxy, a.syy, b.w, b.sx, b.sy, b.sxx, b.sxy, b.syy,
			m_wa, m_sa, m_saa, m_wt, m_st, m_stt, m_lox, m_loy, m_hix, m_hiy, m_capCost};
}

WallEvidence WallEvidence::fromStats(const std::array<double, STATS>& v, uint32_t count)
{
	WallEvidence e;
	size_t i = 0;
	e.m_ax = v[i++], e.m_ay = v[i++], e.m_phi = v[i++];
	for (Face& f : e.m_face) f.w = v[i++], f.sx = v[i++], f.sy = v[i++], f.sxx = v[i++], f.sxy = v[i++], f.syy = v[i++];
	e.m_wa = v[i++], e.m_sa = v[i++], e.m_saa = v[i++], e.m_wt = v[i++], e.m_st = v[i++], e.m_stt = v[i++];
	e.m_lox = v[i++], e.m_loy = v[i++], e.m_hix = v[i++], e.m_hiy = v[i++];
	e.m_capCost = v[i++];
	e.m_count = count;
	return e;
}
}  // namespace whiskermap::model
