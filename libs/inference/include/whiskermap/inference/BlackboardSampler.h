#pragma once
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/SamplerRandom.h>
#include <whiskermap/inference/StepResult.h>
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/inference/moves/MoveRegistry.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/ModelParams.h>

#include <functional>
#include <utility>
#include <vector>

namespace whiskermap::inference
{
/** The annealed blackboard sampler (paper section 5, Algorithm 1): one time step from an
 *  empty blackboard, or one insertion into the lasting map from a given board. It schedules
 *  the moves of the MoveRegistry (moves/, doc/sampler.md) and judges their proposals with its
 *  Acceptance (by default the heuristic Gibbs choice with P^beta(H | mb(H)), eq. 20). Not
 *  thread-safe, not copyable; reuses its buffers across steps. Same shapelets + same seed ->
 *  identical result. */
class BlackboardSampler
{
   public:
	BlackboardSampler(const model::ModelParams& model, const SamplerParams& params);
	BlackboardSampler(const BlackboardSampler&) = delete;
	BlackboardSampler& operator=(const BlackboardSampler&) = delete;

	/** Runs Algorithm 1 on `shapelets` (the working memory). `snapshotTemperature` >= 0
	 *  asks for a copy of the blackboard after the last sweep at that schedule index. */
	StepResult step(
		const std::vector<obs::Shapelet>& shapelets, uint64_t seed, int snapshotTemperature = -1);
	/** Same, with the free space the whiskers swept in the shapelets' sweeps (negative
	 *  evidence, eq. 21: scored when the model's free_space is on). */
	StepResult step(
		const std::vector<obs::Shapelet>& shapelets, const std::vector<obs::SweptSector>& swept, uint64_t seed,
		int snapshotTemperature = -1);

	/** Algorithm 1 from a given board: one insertion into the lasting map (doc/sampler.md,
	 *  "Local annealing"). Shapelets without a leg are first associated greedily (link to a
	 *  nearby leg or a new one, whichever explains them best); that board is the first MAP
	 *  candidate; then the same schedule and polish run, never visiting dormant hypotheses.
	 *  The MAP board is best() afterwards. `start` must use this sampler's model. */
	StepResult anneal(const model::Blackboard& start, uint64_t seed, int snapshotTemperature = -1);
	/** The best board of the last step() or anneal(). */
	const model::Blackboard& best() const { return m_best; }

	const SamplerParams& params() const { return m_params; }

	/** For benchmarks: `w(board, counts so far)` is called after every change of the board
	 *  that stays (an accepted proposal, a search that improved a pose, the association, a
	 *  prune that removed something) in the steps and anneals that follow; empty: none. */
	void watch(std::function<void(const model::Blackboard&, const StepResult&)> w) { m_ctx.watcher = std::move(w); }

   private:
	/** The schedule, the coldest sweeps and the polish from the current board. */
	void run(StepResult& result, uint64_t seed, int snapshotTemperature);
	void associate();
	/** One pass of Algorithm 1's body at inverse temperature beta: every registered move
	 *  offered to its targets, then the prune. */
	void sweep(double beta);
	/** Offers the moves of `target` to hypothesis `id` (one draw u for all of them). */
	void visit(moves::Target target, model::Id id);
	/** If the board beats the best so far, it becomes the MAP candidate. The board is scored
	 *  (eq. 20, the whole board) only when a move was accepted, or the prune removed something,
	 *  since it was last scored: rejected moves leave it exactly as it was
	 *  (MoveRoundTrip.AMoveThatCountsNoAcceptanceLeavesTheBoardAsItWas), so its score and the
	 *  verdict are unchanged. */
	void checkpoint(StepResult& result);
	void prune();
	model::Id bestWallFor(size_t s, double& gain) const;

	model::ModelParams m_model;
	SamplerParams m_params;
	model::Blackboard m_bb;
	SamplerRandom m_rng;
	Acceptance m_acceptance;
	moves::MoveContext m_ctx;  ///< refers to the members above
	moves::MoveRegistry m_moves;

	// Scratch, reused across calls (no per-move heap churn once warm).
	std::vector<model::Id> m_tableOrder, m_legOrder, m_wallOrder, m_candidates;
	model::Blackboard m_best;  ///< the best board at the coldest temperature (the MAP)
	uint64_t m_scoredAfter = NOT_SCORED;  ///< accepted moves when checkpoint last scored the board (NOT_SCORED: score it next time)
	static constexpr uint64_t NOT_SCORED = ~uint64_t{0};
	std::vector<uint8_t> m_legSupported, m_tableSupported;
	std::vector<size_t> m_shapeletMoves;  ///< the registry lines that visit shapelets (priming)
};
}  // namespace whiskermap::inference
