#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>
#include <whiskermap/model/Densities.h>

#include <cmath>
#include <utility>
#include <limits>

namespace whiskermap::model
{
namespace
{
double sq(double v) { return v * v; }
}  // namespace

double logSumExp(double a, double b)
{
	const double m = std::max(a, b);
	if (m == -std::numeric_limits<double>::infinity()) return m;
	return m + std::log1p(std::exp(std::min(a, b) - m));
}

double logCell(double logDensity, const ModelParams& p)
{
	return 3 * core::cachedLog(2 * p.delta) + logDensity;  // eq. 19
}

double logTablePrior(const ModelParams& p) { return core::cachedLog(p.c_T); }  // eq. 4

// eq. 4 with the class: c_T P(class); exactly c_T without a catalogue (log 1 = 0)
double logTablePrior(const Table& t, const ModelParams& p)
{
	return core::cachedLog(p.c_T) + std::log(p.priorOf(t.cls)) + logSizePrior(t, p);
}

// eq. 24: -(d_length^2 + d_width^2) / (2 size_sigma^2); exactly -0 at the nominal size
double logSizePrior(const Table& t, const ModelParams& p)
{
	if (p.classes.empty()) return 0;
	return -(sq(t.d_length) + sq(t.d_width)) / (2 * sq(p.sizeSigmaOf(t.cls))) + logLegPrior(t, p);
}

// eq. 26: -(w - w_k)^2 / (2 leg_width_sigma^2) - (tau - tau_k)^2 / (2 texture_sigma^2), each
// term only for a spread > 0 (a spread of 0 keeps the class's value: the term is 0)
double logLegPrior(const Table& t, const ModelParams& p)
{
	if (p.classes.empty()) return 0;
	const ObjectClass& c = p.classes[t.cls];
	double v = 0;
	if (c.leg_width_sigma > 0) v -= sq(t.leg_width - c.leg_width) / (2 * sq(c.leg_width_sigma));
	if (c.texture_sigma > 0) v -= sq(t.texture - c.texture) / (2 * sq(c.texture_sigma));
	return v;
}

void tableCorner(const Table& t, int i, const ModelParams& p, double& x, double& y)
{
	const double lx = (i == 0 || i == 3 ? 0.5 : -0.5) * p.lengthOf(t);
	const double ly = (i < 2 ? 0.5 : -0.5) * p.widthOf(t);
	const auto [s, c] = core::cachedSinCos(t.theta);
	x = t.x + c * lx - s * ly;
	y = t.y + s * lx + c * ly;
}

void tableCorners(const Table& t, const ModelParams& p, double x[4], double y[4])
{
	const auto [s, c] = core::cachedSinCos(t.theta);
	const double hl = 0.5 * p.lengthOf(t), hw = 0.5 * p.widthOf(t);  // -0.5 * v is -(0.5 * v) exactly
	for (int i = 0; i < 4; i++)
	{
		const double lx = i == 0 || i == 3 ? hl : -hl;
		const double ly = i < 2 ? hw : -hw;
		x[i] = t.x + c * lx - s * ly;
		y[i] = t.y + s * lx + c * ly;
	}
}

int nearestCorner(const double x[4], const double y[4], double px, double py, double& d2)
{
	int best = 0;
	d2 = std::numeric_limits<double>::infinity();
	for (int i = 0; i < 4; i++)
	{
		const double d = sq(x[i] - px) + sq(y[i] - py);
		if (d < d2) d2 = d, best = i;
	}
	return best;
}

OrientedRect tableRect(const Table& t, const ModelParams& p)
{
	return {t.x, t.y, t.theta, p.lengthOf(t) / 2, p.widthOf(t) / 2};
}

OrientedRect legRect(const Leg& l) { return {l.x, l.y, l.theta, l.wx / 2, l.wy / 2}; }

LegFit logLegGivenTable(const Leg& l, const Table& t, const ModelParams& p)
{
	// eq. 6: nearest corner, then angle (modulo the leg's 90 degree symmetry), widths, texture
	LegFit fit{0, 0};
	double cx[4], cy[4], best = 0;
	tableCorners(t, p, cx, cy);
	fit.corner = nearestCorner(cx, cy, l.x, l.y, best);
	const double delta = best / sq(p.sigma_corner) +
						 sq(core::angleDiff(t.theta, l.theta, M_PI_2) / p.sigma_theta) +
						 sq((t.leg_width - l.wx) / p.sigma_w) + sq((t.leg_width - l.wy) / p.sigma_w) +
						 sq((t.texture - l.texture) / p.sigma_tau);
	fit.logDensity = core::cachedLog(p.alpha_L) - delta;  // eq. 5
	return fit;
}

double contactVariance(const obs::Shapelet& s, double ux, double uy, const ModelParams& p)
{
	return p.shaft_noise ? shaftVariance(s, ux, uy, p) : sq(p.sigma_r);
}

double shaftVariance(const obs::Shapelet& s, double ux, double uy, const ModelParams& p)
{
	if (!s.hasShaft()) return sq(p.sigma_r);
	return sq(p.sigma_r * (ux * s.shaft_x + uy * s.shaft_y)) + sq(p.sigma_across);  // shaft noise
}

double alongFaceNormaliser(double faceLength, double variance, const ModelParams& p)
{
	// The excess kernel exp(-e^2 / v) integrates to sqrt(pi v) over both ends: a contact's
	// position along a face of length w has density 1 / (w + sqrt(pi v)). Relative to the
	// model's leg_width (0 there): only its dependence on w.
	const double end = std::sqrt(M_PI * variance);
	return std::log((faceLength + end) / (p.leg_width + end));  // eq. 7, along the face
}

double logShapeletGivenLeg(const obs::Shapelet& s, const Leg& l, const ModelParams& p)
{
	// eq. 7 with the face that explains the contact best: distance to that face (a segment)
	// and the contact's normal against the face's outward normal (mod 360 deg). Faces k = 0..3
	// have outward normals theta + k pi/2; in the leg frame the point is (lx, ly).
	const auto [sn, c] = core::cachedSinCos(l.theta);
	const double dx = s.x - l.x, dy = s.y - l.y;
	const double lx = c * dx + sn * dy, ly = -sn * dx + c * dy, hx = l.wx / 2, hy = l.wy / 2;
	const double ex = std::max(std::abs(lx) - hx, 0.0), ey = std::max(std::abs(ly) - hy, 0.0);
	double cost[4];  // eq. 7's distance term per face
	double vx = sq(p.sigma_r), vy = vx;  // variances along the leg's x and y axes
	if (p.shaft_noise && s.hasShaft())
	{
		// Variances along the leg's x and y axes (the shaft in the leg frame): each face's
		// distance across it, and its excess past the face's ends along it.
		// The across-face distance is a 1-D Gaussian: its density is sigma_r / sigma_across-face
		// times the paper's (the log of that ratio is a gain, nx for faces 0, 2 and ny for 1, 3).
		vx = contactVariance(s, c, sn, p), vy = contactVariance(s, -sn, c, p);
		const double nx = 0.5 * std::log(sq(p.sigma_r) / vx), ny = 0.5 * std::log(sq(p.sigma_r) / vy);
		cost[0] = sq(lx - hx) / vx + sq(ey) / vy - nx, cost[1] = sq(ly - hy) / vy + sq(ex) / vx - ny;
		cost[2] = sq(lx + hx) / vx + sq(ey) / vy - nx, cost[3] = sq(ly + hy) / vy + sq(ex) / vx - ny;
	}
	else
	{
		const double d2[4] = {sq(lx - hx) + sq(ey), sq(ly - hy) + sq(ex), sq(lx + hx) + sq(ey), sq(ly + hy) + sq(ex)};
		for (int k = 0; k < 4; k++) cost[k] = d2[k] / sq(p.sigma_r);
	}
	if (p.legWidthsVary())
	{
		// eq. 7's normaliser along the face, where the leg's width is inferred (eq. 26): faces 0, 2
		// run along y (length wy, variance vy), faces 1, 3 along x.
		const double gy = alongFaceNormaliser(l.wy, vy, p), gx = alongFaceNormaliser(l.wx, vx, p);
		cost[0] += gy, cost[2] += gy, cost[1] += gx, cost[3] += gx;
	}
	double a = core::wrapToPi(s.normal - l.theta);  // normal against face 0's
	double best = std::numeric_limits<double>::infinity();
	for (int k = 0; k < 4; k++, a -= M_PI_2)
	{
		const double ak = a <= -M_PI ? a + 2 * M_PI : a;
		best = std::min(best, cost[k] + sq(ak / p.sigma_theta));
	}
	return core::cachedLog(p.alpha_S) - best - sq((l.texture - s.texture) / p.sigma_tau);  // eq. 7
}

namespace
{
/** Delta_WS of eq. 22 against face `side` (a long face or an end cap: Wall::hit), without
 *  the texture term. */
double wallFaceCost(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, int side, const ModelParams& p)
{
	const Wall::FaceHit h = w.hit(fr, s.x, s.y, side);
	const double a = core::wrapToPi(s.normal - h.normal);
	double position = (sq(h.across) + sq(h.excess)) / sq(p.sigma_r);
	if (p.shaft_noise && s.hasShaft())
	{
		// across the face: the shaft's variance along the face normal; along it: along the face
		const double nx = std::cos(h.normal), ny = std::sin(h.normal);
		const double va = contactVariance(s, nx, ny, p), vl = contactVariance(s, -ny, nx, p);
		position = sq(h.across) / va + sq(h.excess) / vl - 0.5 * std::log(sq(p.sigma_r) / va);
	}
	return position + sq(a / p.sigma_theta);
}

/** The face of eq. 22's minimum for contact s (the first of Wall::FACES on a tie) and its cost. */
std::pair<int, double> bestWallFaceCost(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p)
{
	std::pair<int, double> best{Wall::FACES[0], wallFaceCost(s, w, fr, Wall::FACES[0], p)};
	for (const int f : Wall::FACES)
		if (f != best.first)
			if (const double c = wallFaceCost(s, w, fr, f, p); c < best.second) best = {f, c};
	return best;
}
}  // namespace

int bestWallFace(const obs::Shapelet& s, const Wall& w, const ModelParams& p) { return bestWallFace(s, w, w.frame(), p); }
int bestWallFace(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p)
{
	return bestWallFaceCost(s, w, fr, p).first;
}

double logShapeletGivenWall(const obs::Shapelet& s, const Wall& w, const ModelParams& p)
{
	return logShapeletGivenWall(s, w, w.frame(), p);
}

double logShapeletGivenWall(const obs::Shapelet& s, const Wall& w, const Wall::Frame& fr, const ModelParams& p)
{
	const double best = bestWallFaceCost(s, w, fr, p).second;
	return core::cachedLog(p.alpha_S) - best - sq((w.texture - s.texture) / p.sigma_tau);  // eq. 22
}

double logWallPrior(const Wall& w, const ModelParams& p)
{
	return 4 * core::cachedLog(2 * p.delta) + std::log(p.c_W) - w.length() / p.wall_length_scale;  // eq. 23
}

double logLegNull(const ModelParams& p) { return core::cachedLog(p.c_L); }  // eq. 8
double logShapeletNull(const ModelParams& p) { return core::cachedLog(p.c_S); }  // eq. 9
}  // namespace whiskermap::model
