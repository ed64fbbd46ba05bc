#include <whiskermap/inference/FiniteDifferences.h>
#include <whiskermap/inference/RigidPoseSpread.h>
#include <whiskermap/inference/RigidTableFit.h>
#include <whiskermap/inference/SamplerRandom.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>

namespace whiskermap::inference
{
namespace
{
model::Table moved(model::Table t, const Eigen::Vector3d& u)
{
	t.x += u[0], t.y += u[1], t.theta += u[2];
	return t;
}

/** A square root of the proposal's covariance: 2.38^2 / 3 (-H)^-1 (H: the score's Hessian at
 *  `start` in x, y, yaw, by central differences), or a fixed diagonal where -H is not positive
 *  definite. */
template <class Score>
Eigen::Matrix3d proposalRoot(const model::Table& start, double value, const Score& score)
{
	Eigen::Vector3d g;
	Eigen::Matrix3d H;
	finiteDifferences([&](const Eigen::Vector3d& u) { return score(moved(start, u)); }, value, 1e-4, g, H);
	const Eigen::LLT<Eigen::Matrix3d> curvature(-H);
	if (curvature.info() == Eigen::Success && H.allFinite())
	{
		const Eigen::LLT<Eigen::Matrix3d> root(curvature.solve(Eigen::Matrix3d::Identity()) * (2.38 * 2.38 / 3));
		if (root.info() == Eigen::Success && root.matrixL().toDenseMatrix().allFinite()) return root.matrixL();
	}
	return Eigen::Vector3d(0.002, 0.002, 0.3 * M_PI / 180).asDiagonal();
}
}  // namespace

PoseSpread rigidPoseSpread(
	const model::LastingState& s, model::Id t, const model::Table& start, const model::ModelParams& p, uint64_t seed,
	int samples, int burnIn)
{
	const auto score = [&](const model::Table& table) { return rigidTableScore(s, t, table, p); };
	double value = score(start);
	const Eigen::Matrix3d root = proposalRoot(start, value, score);
	SamplerRandom rng;
	rng.seed(seed);
	Eigen::Vector3d u = Eigen::Vector3d::Zero(), mean = Eigen::Vector3d::Zero(), m2 = Eigen::Vector3d::Zero();
	int accepted = 0;
	for (int k = 0; k < burnIn + samples; k++)
	{
		const Eigen::Vector3d v = u + root * Eigen::Vector3d(rng.gaussian(), rng.gaussian(), rng.gaussian());
		const double candidate = score(moved(start, v));
		if (std::log(rng.uniform()) < candidate - value)  // Metropolis at beta = 1 (symmetric proposal)
			u = v, value = candidate, accepted += k >= burnIn;
		if (k < burnIn) continue;
		const int n = k - burnIn + 1;  // Welford's running variance
		const Eigen::Vector3d d = u - mean;
		mean += d / n;
		m2 += d.cwiseProduct(u - mean);
	}
	PoseSpread out;
	if (samples < 2) return out;
	const Eigen::Vector3d sd = (m2 / (samples - 1)).cwiseSqrt();
	out.sd_x = sd[0], out.sd_y = sd[1], out.sd_yaw = sd[2];
	out.acceptance = static_cast<double>(accepted) / samples;
	return out;
}
}  // namespace whiskermap::inference
