#include <whiskermap/core/Angles.h>
#include <whiskermap/model/Densities.h>

#include <cmath>
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
	return 3 * std::log(2 * p.delta) + logDensity;  // eq. 19
}

double logTablePrior(const ModelParams& p) { return std::log(p.c_T); }  // eq. 4

void tableCorner(const Table& t, int i, const ModelParams& p, double& x, double& y)
{
	const double lx = (i == 0 || i == 3 ? 0.5 : -0.5) * p.table_length;
	const double ly = (i < 2 ? 0.5 : -0.5) * p.table_width;
	const double c = std::cos(t.theta), s = std::sin(t.theta);
	x = t.x + c * lx - s * ly;
	y = t.y + s * lx + c * ly;
}

OrientedRect tableRect(const Table& t, const ModelParams& p)
{
	return {t.x, t.y, t.theta, p.table_length / 2, p.table_width / 2};
}

OrientedRect legRect(const Leg& l) { return {l.x, l.y, l.theta, l.wx / 2, l.wy / 2}; }

LegFit logLegGivenTable(const Leg& l, const Table& t, const ModelParams& p)
{
	// eq. 6: nearest corner, then angle (modulo the leg's 90 degree symmetry), widths, texture
	LegFit fit{0, 0};
	double best = std::numeric_limits<double>::infinity();
	for (int i = 0; i < 4; i++)
	{
		double cx = 0, cy = 0;
		tableCorner(t, i, p, cx, cy);
		const double d2 = sq(cx - l.x) + sq(cy - l.y);
		if (d2 < best)
		{
			best = d2;
			fit.corner = i;
		}
	}
	const double delta = best / sq(p.sigma_r) +
						 sq(core::angleDiff(t.theta, l.theta, M_PI_2) / p.sigma_theta) +
						 sq((t.leg_width - l.wx) / p.sigma_w) + sq((t.leg_width - l.wy) / p.sigma_w) +
						 sq((t.texture - l.texture) / p.sigma_tau);
	fit.logDensity = std::log(p.alpha_L) - delta;  // eq. 5
	return fit;
}

double logShapeletGivenLeg(const obs::Shapelet& s, const Leg& l, const ModelParams& p)
{
	// eq. 7 with the face that explains the contact best: distance to that face (a segment)
	// and the contact's normal against the face's outward normal (mod 360 deg).
	const OrientedRect r = legRect(l);
	double best = std::numeric_limits<double>::infinity();
	for (int k = 0; k < 4; k++)
		best = std::min(
			best, sq(r.faceDistance(s.x, s.y, k) / p.sigma_r) +
					  sq(core::angleDiff(s.normal, l.theta + k * M_PI_2, 2 * M_PI) / p.sigma_theta));
	return std::log(p.alpha_S) - best - sq((l.texture - s.texture) / p.sigma_tau);  // eq. 7
}

double logLegNull(const ModelParams& p) { return std::log(p.c_L); }  // eq. 8
double logShapeletNull(const ModelParams& p) { return std::log(p.c_S); }  // eq. 9
}  // namespace whiskermap::model
