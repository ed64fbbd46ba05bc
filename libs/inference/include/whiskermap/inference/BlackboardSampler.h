#pragma once
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/StepResult.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/ModelParams.h>

#include <random>
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

	const SamplerParams& params() const { return m_params; }

   private:
	void sweep(double beta);
	void prime(size_t shapelet, double beta);
	void visitTable(model::Id t, double beta);
	void visitLeg(model::Id l, double beta);
	void proposeLegReparent(model::Id l, double beta);
	void proposeLegChild(model::Id l, double beta);
	void proposeTableChild(model::Id t, double beta);
	void proposeTableForLeg(model::Id l, double beta);
	void prune();
	double alongFace(size_t shapelet);
	/** True if a leg of `table` not in `except` explains a shapelet. */
	bool hasSupportedLeg(model::Id table, const std::vector<model::Id>& except) const;
	/** Removes `table` and then its (unsupported) legs; returns the change of logJoint. */
	double removeTableAndOrphans(model::Id table);
	/** The table of the known size with `leg` at `corner`, turned by `turn` from its yaw. */
	model::Table tableWithLegAt(const model::Leg& leg, int corner, double turn) const;
	/** Fills m_candidates with the legs other than `l` that table `t` would adopt; their count. */
	size_t adoptable(const model::Table& t, model::Id l);

	/** Counts the proposal and draws its acceptance from the annealed conditional. */
	bool accept(Move m, double logOdds, double beta);
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


	// Scratch, reused across calls (no per-move heap churn once warm).
	std::vector<model::Id> m_tableOrder, m_legOrder, m_candidates, m_oldParents,
		m_abandoned, m_orphans;
	model::Blackboard m_backup;  ///< state before a compound move, to undo it
	std::vector<uint8_t> m_legSupported, m_tableSupported;
};
}  // namespace whiskermap::inference
