#pragma once
#include <whiskermap/model/Id.h>
#include <whiskermap/model/LastingState.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/Table.h>

#include <cstdint>

namespace whiskermap::inference
{
/** The posterior spread of a table's pose: standard deviations of its centre (metres) and yaw
 *  (radians) over the samples of a chain, and the chain's acceptance rate. */
struct PoseSpread
{
	double sd_x = 0, sd_y = 0, sd_yaw = 0;
	double acceptance = 0;
};

/** The spread of lasting table t's rigid pose given its contacts (doc/map-plugin.md, "Pose
 *  spread"): a random-walk Metropolis chain at beta = 1 on rigidTableScore (eq. 7 summed over
 *  every contact of its legs, the legs rigid at their corners; a flat prior on the pose), from
 *  `start` (fitRigidTable's answer: the mode). Proposals are N(0, 2.38^2 / 3 Sigma), Sigma the
 *  inverse of minus the score's Hessian at `start` (central differences), or 2 mm, 2 mm,
 *  0.3 deg per axis where the score is not concave there; symmetric, so the acceptance is
 *  min(1, exp(score' - score)) and the chain's stationary distribution is the posterior.
 *  `burnIn` steps, then `samples` counted. Seeded: same arguments, same answer. */
PoseSpread rigidPoseSpread(
	const model::LastingState& s, model::Id t, const model::Table& start, const model::ModelParams& p, uint64_t seed,
	int samples = 2000, int burnIn = 200);
}  // namespace whiskermap::inference
