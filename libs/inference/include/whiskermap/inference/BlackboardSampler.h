#pragma once
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/StepResult.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/ModelParams.h>

#include <random>
#include <utility>
#include <vector>

namespace whiskermap::inference
{
/** The annealed blackboard sampler (paper section 5, Algorithm 1): one time step from an
 *  empty blackboard, heuristic Gibbs acceptance with P^beta(H | mb(H)) (eq. 20),
 *  geometric data-driven proposals (doc/sampler.md). Not thread-safe; reuses its buffers
 *  across steps. Same shapelets + same seed -> identical result. */
class BlackboardSampler
{
   public:
	BlackboardSampler(const model::ModelParams& model, const SamplerParams& params);

	/** Runs Algorithm 1 on `shapelets` (the working memory). `snapshotTemperature` >= 0
	 *  asks for a copy of the blackboard after the last sweep at that schedule index. */
	StepResult step(
		const std::vector<obs::Shapelet>& shapelets, uint64_t seed, int snapshotTemperature = -1);

	/** Algorithm 1 from a given board: one insertion into the lasting map (doc/sampler.md,
	 *  "Local annealing"). Shapelets without a leg are first associated greedily (link to a
	 *  nearby leg or a new one, whichever explains them best); that board is the first MAP
	 *  candidate; then the same schedule and polish run, never visiting dormant hypotheses.
	 *  The MAP board is best() afterwards. `start` must use this sampler's model. */
	StepResult anneal(const model::Blackboard& start, uint64_t seed, int snapshotTemperature = -1);
	/** The best board of the last step() or anneal(). */
	const model::Blackboard& best() const { return m_best; }

	const SamplerParams& params() const { return m_params; }

   private:
	/** The schedule, the coldest sweeps and the polish from the current board. */
	void run(StepResult& result, uint64_t seed, int snapshotTemperature);
	void associate();
	void sweep(double beta);
	/** If the board beats the best so far, it becomes the MAP candidate. */
	void checkpoint(StepResult& result);
	void prime(size_t shapelet, double beta);
	/** One move drawn by r1..r4, or every move in turn at beta = inf (the greedy polish). */
	void visitTable(model::Id t, double beta);
	void visitLeg(model::Id l, double beta);
	void proposeTableDeath(model::Id t, double beta);
	void proposeLegReparent(model::Id l, double beta);
	void proposeLegChild(model::Id l, double beta);
	void proposeLink(size_t shapelet, model::Id l, Move m, double beta);
	void proposeSplit(size_t shapelet, double beta);
	/** Merge: every contact of leg `other` moves to leg `l`, `other` is removed and `l`
	 *  refits to all its contacts (the reverse of splits). Exact change of logJoint; undone
	 *  on rejection. False if not proposed (nothing to move, or the fit leaves the gate). */
	bool proposeMerge(model::Id l, model::Id other, double beta);
	/** Fills m_mergeable with the legs other than `l` that explain a shapelet and stand near
	 *  enough for one leg to explain both legs' contacts. */
	void mergeCandidates(model::Id l);
	/** Greedy compass search of leg l's pose on its exact local log-odds (the polish). */
	void searchLegPose(model::Id l);
	/** A new free leg for shapelet s, with s on its face (Q(pa(S)), doc/sampler.md). */
	model::Leg newLegFor(size_t s);
	void proposeTableChild(model::Id t, double beta);
	void proposeTableForLeg(model::Id l, double beta);
	void proposeLegRefit(model::Id l, double beta);
	void proposeTableRefit(model::Id t, double beta);
	void prune();
	double alongFace(size_t shapelet);
	/** True if a leg of `table` not in `except` explains a shapelet. */
	bool hasSupportedLeg(model::Id table, const std::vector<model::Id>& except) const;
	/** Closed-form pose (PoseFit.h) of leg `l` for its contacts (m_contacts, filled here) and,
	 *  with `t`, the corner of `t` nearest to it. False if there is nothing to fit or the fit
	 *  leaves a contact or the corner outside the parent gate. */
	bool fittedLeg(model::Id l, const model::Table* t, model::Leg& out);
	/** Moves leg l to its fitted pose (if valid: returns true) and adds the change of logJoint
	 *  to `gain`. */
	bool refitInPlace(model::Id l, double& gain);

	/** Counts the proposal and draws its acceptance from the annealed conditional; at
	 *  beta = inf, accepts exactly the improvements. */
	bool accept(Move m, double logOdds, double beta);
	bool draw(double logOdds, double beta);
	double uniform();
	size_t pick(size_t n);
	double gaussian();

	/** Legs whose perimeter is within the parent gate of shapelet `s`. */
	void legsNearShapelet(size_t s, std::vector<model::Id>& out) const;

	model::ModelParams m_model;
	SamplerParams m_params;
	model::Blackboard m_bb;
	std::mt19937_64 m_rng;
	StepResult* m_result = nullptr;
	bool m_searchPoses = false;  ///< the last polish sweep also searches leg poses


	// Scratch, reused across calls (no per-move heap churn once warm).
	std::vector<model::Id> m_tableOrder, m_legOrder, m_candidates, m_oldParents,
		m_abandoned, m_orphans, m_mergeable;
	std::vector<model::Id> m_moved;
	model::Blackboard m_backup;  ///< state before a compound move, to undo it
	model::Blackboard m_best;  ///< the best board at the coldest temperature (the MAP)
	std::vector<const obs::Shapelet*> m_contacts;
	std::vector<const model::Leg*> m_fitLegs;
	std::vector<int> m_fitCorners;
	std::vector<std::pair<model::Id, model::Leg>> m_savedLegs;
	std::vector<model::Table> m_tables;
	std::vector<double> m_weights;
	std::vector<uint8_t> m_legSupported, m_tableSupported;
};
}  // namespace whiskermap::inference
