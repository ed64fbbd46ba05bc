#pragma once
#include <whiskermap/inference/SamplerRandom.h>
#include <whiskermap/inference/moves/Proposal.h>

namespace whiskermap::inference
{
/** The sampler's acceptance of a move's Proposal (doc/sampler.md, "Acceptance"): the
 *  paper's heuristic Gibbs choice with the annealed Markov-blanket conditional
 *  P^beta(H | mb(H)) (eq. 20), whatever the proposal densities. At beta = inf (the greedy
 *  polish) exactly the improvements are accepted. */
class Acceptance
{
   public:
	/** Draws the decision for `p` at inverse temperature `beta` (one uniform from `rng`
	 *  unless beta = inf). */
	bool accept(const moves::Proposal& p, double beta, SamplerRandom& rng) const;
};
}  // namespace whiskermap::inference
