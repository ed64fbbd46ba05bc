#pragma once
#include <whiskermap/inference/StepResult.h>

namespace whiskermap::inference::moves
{
/** What one move proposed (doc/sampler.md, "Moves"): the exact change of the target and the
 *  log densities of the proposal both ways. A move proposes, the sampler's acceptance judges
 *  the Proposal, and the move finishes (keeps the new board or restores the old one). */
struct Proposal
{
	Move kind = Move::Refit;  ///< for counting (StepResult)
	/** log p(new) - log p(old): the exact change of logJoint (eq. 14), computed locally (eq. 20). */
	double logTarget = 0;
	/** log q(new | old): the density of the random choices this move made (discrete choices
	 *  as log-probabilities, continuous draws as log-densities); 0 when deterministic. */
	double logForward = 0;
	/** log q(old | new): the density with which this move's declared reverse proposes the
	 *  old board from the new one; -inf when no reverse move can (doc/sampler.md says which). */
	double logReverse = 0;
	/** log |J| of a dimension-matching transform: 0 for every current move (births draw the
	 *  new parameters themselves; refits are deterministic, not transforms). */
	double logJacobian = 0;
};
}  // namespace whiskermap::inference::moves
