#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/model/Posterior.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::inference
{
bool Acceptance::accept(const moves::Proposal& p, double beta, SamplerRandom& rng) const
{
	if (std::isinf(beta)) return p.logTarget > 0;
	if (m_rule == AcceptanceRule::Gibbs) return rng.uniform() < model::annealedAcceptance(p.logTarget, beta);  // eq. 20
	// Green 1995: the Metropolis-Hastings-Green ratio, annealed target.
	const double logRatio = beta * p.logTarget + p.logReverse - p.logForward + p.logJacobian;
	return rng.uniform() < std::exp(std::min(0.0, logRatio));
}
}  // namespace whiskermap::inference
