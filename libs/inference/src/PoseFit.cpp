#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace whiskermap::inference
{
namespace
{
double sq(double v) { return v * v; }
}  // namespace

void addCentreEquations(
	const model::ModelParams& p, const obs::Shapelet* const* s, size_t n, double theta,
	const model::LegEvidence* evidence, CentreEquations& eq, double w)
{
	for (size_t i = 0; i < n; i++)
	{
		const double f = s[i]->normal - core::angleDiff(s[i]->normal, theta, M_PI_2);
		const double ux = std::cos(f), uy = std::sin(f);
		const double d = ux * s[i]->x + uy * s[i]->y - w / 2;
		// weight in units of 1/sigma_r^2: exactly 1, or more across a shaft (shaft noise, eq. 7)
		const double k = sq(p.sigma_r) / model::contactVariance(*s[i], ux, uy, p);
		eq.a11 += k * ux * ux, eq.a12 += k * ux * uy, eq.a22 += k * uy * uy, eq.b1 += k * ux * d, eq.b2 += k * uy * d;
	}
	if (evidence && !evidence->empty())
		evidence->addCentreEquations(theta, w, p, eq.a11, eq.a12, eq.a22, eq.b1, eq.b2);
}

model::Leg fitLeg(
	const model::ModelParams& p, const obs::Shapelet* const* s, size_t n, const model::Table* t, double qx,
	double qy, double pull, const model::LegEvidence* evidence)
{
	const double w = t ? t->leg_width : p.leg_width;  // a leg of a table has its class's leg width
	double evWeight = 0;
	const bool folded = evidence && !evidence->empty();
	const double evYaw = folded ? evidence->meanYaw(p, evWeight) : 0;
	// Yaw: the mean (mod 90 deg) around each reference angle; keep the one of least cost.
	double theta = t ? t->theta : folded ? evYaw : 0, bestCost = std::numeric_limits<double>::infinity();
	for (int ref = -2; ref < static_cast<int>(n); ref++)
	{
		if ((ref == -2 && !folded) || (ref == -1 && !t)) continue;
		const double a0 = ref == -2 ? evYaw : ref == -1 ? t->theta : s[ref]->normal;
		double sum = t ? core::angleDiff(t->theta, a0, M_PI_2) : 0;
		double count = t ? 1 : 0;
		if (folded) sum += evWeight * core::angleDiff(evYaw, a0, M_PI_2), count += evWeight;
		for (size_t i = 0; i < n; i++) sum += core::angleDiff(s[i]->normal, a0, M_PI_2), count++;
		const double th = a0 + sum / count;
		double cost = t ? sq(core::angleDiff(t->theta, th, M_PI_2)) : 0;
		if (folded) cost += evWeight * sq(core::angleDiff(evYaw, th, M_PI_2));
		for (size_t i = 0; i < n; i++) cost += sq(core::angleDiff(s[i]->normal, th, M_PI_2));
		if (cost < bestCost) bestCost = cost, theta = th;
	}
	// Centre: each contact on the line of its face (outward normal u), plus the pull.
	CentreEquations eq{pull, 0, pull, pull * qx, pull * qy};
	addCentreEquations(p, s, n, theta, evidence, eq, w);
	const auto& [a11, a12, a22, b1, b2] = eq;
	const double det = a11 * a22 - a12 * a12;
	double px = (a22 * b1 - a12 * b2) / det, py = (a11 * b2 - a12 * b1) / det;
	// Contacts on the faces of one axis only leave the leg free along those faces (but for the
	// pull): slide it so that their contacts lie on the faces, not past their ends (eq. 7
	// counts the distance past a corner), or centre it on them if they spread wider.
	double axisWeight[2] = {0, 0};
	if (folded) evidence->axisWeights(theta, axisWeight[0], axisWeight[1]);
	for (size_t i = 0; i < n; i++)
		axisWeight[static_cast<int>(std::lround(core::angleDiff(s[i]->normal, theta, 2 * M_PI) / M_PI_2)) & 1] += 1;
	for (int axis = 0; axis < 2; axis++)
	{
		if (axisWeight[axis] == 0 || axisWeight[1 - axis] > 0) continue;
		// Along the faces of `axis`: the direction of the other axis.
		const double vx = -std::sin(theta + axis * M_PI_2), vy = std::cos(theta + axis * M_PI_2);
		double lo = std::numeric_limits<double>::infinity(), hi = -lo;
		for (size_t i = 0; i < n; i++)
		{
			const double a = vx * (s[i]->x - px) + vy * (s[i]->y - py);
			lo = std::min(lo, a), hi = std::max(hi, a);
		}
		if (lo > hi) continue;  // only folded contacts: the pull decides
		const double shift = hi - lo >= w ? (lo + hi) / 2 : std::max(0.0, hi - w / 2) + std::min(0.0, lo + w / 2);
		px += vx * shift, py += vy * shift;
	}
	double texture = t ? t->texture : 0, textureWeight = n + (t ? 1 : 0);
	for (size_t i = 0; i < n; i++) texture += s[i]->texture;
	if (folded)
	{
		double tw = 0;
		const double mean = evidence->meanTexture(p, tw);
		texture += tw * mean, textureWeight += tw;
	}
	model::Leg l;
	l.x = px;
	l.y = py;
	l.theta = theta;
	l.wx = l.wy = w;
	l.texture = texture / textureWeight;
	return l;
}

model::Table fitTableSize(
	const model::ModelParams& p, const model::Table& start, const model::Leg* const* legs, const int* corners,
	size_t n)
{
	const auto [sn, c] = core::cachedSinCos(start.theta);
	const double w = 1 / sq(p.sigma_corner), k = 1 / sq(p.sizeSigmaOf(start.cls)), count = static_cast<double>(n);
	// Per axis (0: length, along x; 1: width, along y): sums of s_i, u_i and s_i u_i.
	double S[2] = {0, 0}, U[2] = {0, 0}, SU[2] = {0, 0};
	for (size_t i = 0; i < n; i++)
	{
		const double dx = legs[i]->x - start.x, dy = legs[i]->y - start.y;
		const double u[2] = {c * dx + sn * dy, -sn * dx + c * dy};
		const double s[2] = {corners[i] == 0 || corners[i] == 3 ? 1.0 : -1.0, corners[i] < 2 ? 1.0 : -1.0};
		for (int a = 0; a < 2; a++) S[a] += s[a], U[a] += u[a], SU[a] += s[a] * u[a];
	}
	const double nominal[2] = {p.lengthOf(start.cls), p.widthOf(start.cls)};
	double offset[2], spacing[2];
	for (int a = 0; a < 2; a++)
	{
		// eqs. 6 + 24: [n w, w S/2; w S/2, n w/4 + k] [offset; spacing] = [w U; w SU/2 + k b_k]
		const double m00 = count * w, m01 = w * S[a] / 2, m11 = count * w / 4 + k;
		const double r0 = w * U[a], r1 = w * SU[a] / 2 + k * nominal[a], det = m00 * m11 - m01 * m01;
		offset[a] = (m11 * r0 - m01 * r1) / det;
		spacing[a] = (m00 * r1 - m01 * r0) / det;
	}
	model::Table t = start;
	t.x = start.x + c * offset[0] - sn * offset[1];
	t.y = start.y + sn * offset[0] + c * offset[1];
	t.d_length = spacing[0] - nominal[0];
	t.d_width = spacing[1] - nominal[1];
	return t;
}

model::Table fitTable(
	const model::ModelParams& p, const model::Table& start, const model::Leg* const* legs, const int* corners,
	size_t n)
{
	model::Table origin = start;  // corner offsets in the table frame
	origin.x = origin.y = origin.theta = 0;
	double ox[4], oy[4], mox = 0, moy = 0, mqx = 0, mqy = 0;
	model::tableCorners(origin, p, ox, oy);
	for (size_t i = 0; i < n; i++)
		mox += ox[corners[i]], moy += oy[corners[i]], mqx += legs[i]->x, mqy += legs[i]->y;
	mox /= n, moy /= n, mqx /= n, mqy /= n;
	// Procrustes: the rotation taking the centred corners onto the centred legs.
	double dot = 0, cross = 0, spread = 0;
	for (size_t i = 0; i < n; i++)
	{
		const double ax = ox[corners[i]] - mox, ay = oy[corners[i]] - moy;
		const double bx = legs[i]->x - mqx, by = legs[i]->y - mqy;
		dot += ax * bx + ay * by, cross += ax * by - ay * bx, spread += ax * ax + ay * ay;
	}
	const double procrustes = spread > 0 ? std::atan2(cross, dot) : start.theta;
	// Both yaw terms are quadratic near the optimum: weight each by its curvature.
	const double kPos = spread / sq(p.sigma_corner), kYaw = 1 / sq(p.sigma_theta);
	double yawSum = 0;
	for (size_t i = 0; i < n; i++) yawSum += core::angleDiff(legs[i]->theta, procrustes, M_PI_2);
	model::Table t = start;
	t.theta = procrustes + kYaw * yawSum / (kPos + kYaw * static_cast<double>(n));
	const auto [sn, c] = core::cachedSinCos(t.theta);
	t.x = mqx - (c * mox - sn * moy);
	t.y = mqy - (sn * mox + c * moy);
	return t;
}

double searchLegPose(model::Blackboard& bb, model::Id l, double tolerance, uint64_t* evaluations)
{
	model::Leg best = bb.leg(l);
	const double start = model::logOddsLeg(bb, l);
	const double value = compassSearch(best, bb.params().leg_width, start, tolerance, [&](const model::Leg& c) {
		if (evaluations) ++*evaluations;
		bb.setLeg(l, c);
		return model::logOddsLeg(bb, l);
	});
	bb.setLeg(l, best);
	return value - start;
}
}  // namespace whiskermap::inference
