#pragma once
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/RandomScan.h>
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/SamplerRandom.h>
#include <whiskermap/model/Blackboard.h>

#include <vector>

namespace whiskermap::inference
{
/** Issue 10's posterior, not only a MAP (doc/sampler.md, "A posterior from a chain"): a chain
 *  at beta = 1 started at a (MAP) board, the library's random scan (moves::libraryScan)
 *  judged by the reversible-jump rule with stochastic refits, so that it targets the model's
 *  posterior over tables and legs (walls held fixed). Each table of the start board gets the
 *  fraction of samples holding it, and the spread of its pose over those samples. A sample
 *  holds table T if it has a table of T's class whose centre is within T's leg width of T's
 *  (T's mirror image, or T with another corner assignment, stands a table's width away). */
class PosteriorChain
{
   public:
	struct Summary
	{
		double existence = 0;  ///< fraction of the samples holding the table
		double sd_x = 0, sd_y = 0, sd_yaw = 0;  ///< pose spread over the samples holding it (yaw mod pi)
	};

	/** `params`: the sampler's, with the acceptance set to reversible_jump and data-driven
	 *  proposals. */
	PosteriorChain(const model::ModelParams& model, SamplerParams params);
	PosteriorChain(const PosteriorChain&) = delete;
	PosteriorChain& operator=(const PosteriorChain&) = delete;

	/** `burnIn` scan steps from `start`, then `samples` samples one every `thin` steps; the
	 *  summary of every live table of `start` by id (unused ids: zeros). Same board and seed,
	 *  same result. */
	std::vector<Summary> run(const model::Blackboard& start, uint64_t seed, long burnIn, long samples, long thin);

	/** The scan (its moves' weights may be changed; its counts accumulate over runs). */
	RandomScan& scan() { return m_scan; }

   private:
	model::ModelParams m_model;
	SamplerParams m_params;
	Acceptance m_acceptance{AcceptanceRule::ReversibleJump};
	RandomScan m_scan;
	model::Blackboard m_bb;
	SamplerRandom m_rng;
};
}  // namespace whiskermap::inference
