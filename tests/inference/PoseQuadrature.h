#pragma once
// Posterior moments and integrals of a pose (x, y, yaw) by quadrature, for the tests of the
// reversible-jump moves on continuous poses (StochasticRefits_unittest, ReversibleJumpCells_unittest).
#include <whiskermap/model/Posterior.h>

#include <array>
#include <cmath>
#include <functional>

namespace whiskermap::test
{
using Pose = std::array<double, 3>;  // x, y, yaw

struct Moments
{
	Pose mean{}, var{};
	double logIntegral = 0;  ///< log of the integral of exp(logp) over the pose (quadrature only)
};

/** Posterior mean and variance of a pose with log density `logp` (up to a constant), and the
 *  integral of exp(logp), by quadrature: a grid of n^3 points over +-7 standard deviations of the Laplace approximation
 *  at `mode` along its Cholesky axes (so correlated coordinates are covered too). */
inline Moments quadrature(const std::function<double(const Pose&)>& logp, const Pose& mode, int n = 61)
{
	double H[3][3];  // minus the Hessian, by central differences
	const double h[3] = {1e-4, 1e-4, 1e-4};
	const auto at = [&](int a, double da, int b, double db) {
		Pose p = mode;
		p[a] += da, p[b] += db;
		return logp(p);
	};
	for (int a = 0; a < 3; a++)
		for (int b = 0; b < 3; b++)
			H[a][b] = -(at(a, h[a], b, h[b]) - at(a, h[a], b, -h[b]) - at(a, -h[a], b, h[b]) + at(a, -h[a], b, -h[b])) /
					  (4 * h[a] * h[b]);
	double L[3][3] = {};  // H = L L^T
	for (int i = 0; i < 3; i++)
		for (int j = 0; j <= i; j++)
		{
			double sum = H[i][j];
			for (int k = 0; k < j; k++) sum -= L[i][k] * L[j][k];
			L[i][j] = i == j ? std::sqrt(sum) : sum / L[j][j];
		}
	// p = mode + L^-T z: solve L^T d = z (back substitution).
	const auto offset = [&](const Pose& z) {
		Pose d{};
		for (int i = 2; i >= 0; i--)
		{
			double sum = z[static_cast<size_t>(i)];
			for (int k = i + 1; k < 3; k++) sum -= L[k][i] * d[static_cast<size_t>(k)];
			d[static_cast<size_t>(i)] = sum / L[i][i];
		}
		return d;
	};
	const double top = logp(mode);
	double w = 0;
	Pose m1{}, m2{};
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++)
			for (int k = 0; k < n; k++)
			{
				const auto z = [&](int q) { return -7 + 14.0 * q / (n - 1); };
				const Pose d = offset({z(i), z(j), z(k)});
				Pose p = mode;
				for (size_t a = 0; a < 3; a++) p[a] += d[a];
				const double wi = std::exp(logp(p) - top);
				w += wi;
				for (size_t a = 0; a < 3; a++) m1[a] += wi * p[a], m2[a] += wi * p[a] * p[a];
			}
	Moments out;
	for (size_t a = 0; a < 3; a++) out.mean[a] = m1[a] / w, out.var[a] = m2[a] / w - out.mean[a] * out.mean[a];
	const double dz = 14.0 / (n - 1);  // the grid's volume element: dz^3 / det L
	out.logIntegral = top + std::log(w) + 3 * std::log(dz) - std::log(L[0][0] * L[1][1] * L[2][2]);
	return out;
}

/** The pose of a table or leg. */
template <class H>
Pose poseOf(const H& h)
{
	return {h.x, h.y, h.theta};
}

/** logJoint of `bb` with a table or leg (now `current`) moved to pose p by `set`, then set back. */
template <class H, class Set>
double logJointAt(const model::Blackboard& bb, const H& current, const Pose& p, Set&& set)
{
	const H old = current;
	H moved = old;
	moved.x = p[0], moved.y = p[1], moved.theta = p[2];
	set(moved);
	const double out = model::logJoint(bb);
	set(old);
	return out;
}
}  // namespace whiskermap::test
