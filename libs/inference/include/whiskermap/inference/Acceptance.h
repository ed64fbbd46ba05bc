#pragma once
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/SamplerRandom.h>
#include <whiskermap/inference/moves/Proposal.h>

namespace whiskermap::inference
{
/** The sampler's acceptance of a move's Proposal (doc/sampler.md, "Acceptance"). Gibbs (the
 *  default): the paper's heuristic choice with the annealed Markov-blanket conditional
 *  P^beta(H | mb(H)) (eq. 20), whatever the proposal densities. ReversibleJump (Green 1995):
 *  min(1, exp(beta logTarget + logReverse - logForward + logJacobian)), the annealing acting
 *  on the target only; a move with no reverse (logReverse = -inf) is never accepted. At
 *  beta = inf (the greedy polish) both accept exactly the improvements. */
class Acceptance
{
   public:
	explicit Acceptance(AcceptanceRule rule = AcceptanceRule::Gibbs) : m_rule(rule) {}

	/** Draws the decision for `p` at inverse temperature `beta` (one uniform from `rng`
	 *  unless beta = inf). */
	bool accept(const moves::Proposal& p, double beta, SamplerRandom& rng) const;

   private:
	AcceptanceRule m_rule;
};
}  // namespace whiskermap::inference
