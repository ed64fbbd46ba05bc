#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>

namespace whiskermap::inference
{
bool Acceptance::accept(const moves::Proposal& p, double beta, SamplerRandom& rng) const
{
	if (std::isinf(beta)) return p.logTarget > 0;
	return rng.uniform() < model::annealedAcceptance(p.logTarget, beta);  // eq. 20
}
}  // namespace whiskermap::inference
