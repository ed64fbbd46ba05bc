#pragma once
#include <whiskermap/core/IniSection.h>
#include <whiskermap/inference/AnnealingSchedule.h>

namespace whiskermap::inference
{
/** How the sampler accepts a move's proposal (Acceptance.h, doc/sampler.md "Acceptance"). */
enum class AcceptanceRule
{
	Gibbs,  ///< the paper's heuristic: P^beta(H | mb(H)) (eq. 20), proposal densities ignored
	ReversibleJump,  ///< Green 1995: min(1, (p'/p)^beta q(reverse) / q(forward) |J|)
};

/** Where the moves put what they propose (doc/sampler.md, "Broad proposals"). */
enum class Proposals
{
	DataDriven,  ///< contacts on faces, closed-form fits, pair tables, adoption weights, pose search
	Broad,  ///< the baseline: poses drawn near the contact or as random-walk steps, nothing fitted
};

/** Settings of the annealed blackboard sampler (Algorithm 1). Defaults and reasons:
 *  config/whisker-map.ini [MetricMap_hierarchicalObjectMap_00_sampler], doc/sampler.md. */
struct SamplerParams
{
	/** Move thresholds on u ~ U(0,1) per hypothesis: death below r1, new parent below r2,
	 *  child below r3, pose refit below r4, else a parent proposal.
	 *  0 <= r1 <= r2 <= r3 <= r4 <= 1. */
	double r1 = 0.2, r2 = 0.35, r3 = 0.55, r4 = 0.75;

	AnnealingSchedule schedule = AnnealingSchedule::geometric(0.1, 10.0, 12);
	int sweeps_per_temperature = 2;  ///< priming + hypothesis sweep + prune, per beta
	int coldest_sweeps = 6;  ///< sweeps at the last beta; each is a MAP checkpoint
	/** Greedy sweeps (zero temperature) from the best board: every move offered to every
	 *  hypothesis, only improvements accepted; each is a MAP checkpoint. */
	int polish_sweeps = 2;

	/** Priming: probability of proposing an existing leg near the shapelet (when there is
	 *  one) rather than a new leg. */
	double existing_leg_probability = 0.5;
	/** Leg child move: probability of proposing a merge with a nearby leg (when there is
	 *  one and no split was drawn) rather than a link of one nearby contact. */
	double merge_probability = 0.5;
	double leg_position_noise = 0.003;  ///< std-dev of a new leg's centre, metres
	double leg_angle_noise = 0.02;  ///< std-dev of a new leg's yaw, radians
	/** Key `acceptance` (optional): `gibbs` (default) or `reversible_jump`. */
	AcceptanceRule acceptance = AcceptanceRule::Gibbs;
	/** Key `proposals` (optional): `data_driven` (default) or `broad` (issue 10's baseline). */
	Proposals proposals = Proposals::DataDriven;
	/** Key `posterior_steps` (optional, default 0): steps of the posterior chain
	 *  (PosteriorChain, doc/sampler.md "A posterior from a chain") after each lasting-map
	 *  insertion: the first fifth burn-in, then every 5th state a sample; the tables' existence
	 *  is then the chain's. 0: existence from TableExistence. */
	long posterior_steps = 0;

	/** Reads every key of `sec` (all required but `acceptance`, `proposals` and `posterior_steps`; the schedule as beta_start,
	 *  beta_end, temperatures) and calls sec.finish(); throws core::Error. */
	static SamplerParams fromIni(core::IniSection& sec);
	/** Every setting equal (the schedule's betas included). */
	bool operator==(const SamplerParams& o) const;
};
}  // namespace whiskermap::inference
