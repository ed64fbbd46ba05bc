#pragma once
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/RigidPoseSpread.h>
#include <whiskermap/model/LastingState.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace whiskermap::maps
{
struct LastingWorkspace;

/** The lasting map (doc/map-plugin.md): one hierarchical state (model::LastingState) that
 *  every inserted sweep updates where its contacts fall. An insertion adds the sweep's
 *  contacts, cuts the local problem around them out of the state, associates them with the
 *  legs there and anneals it (inference::BlackboardSampler::anneal: earlier decisions nearby
 *  can be revised), scores each table's existence (inference::TableExistence), writes the
 *  result back, merges legs that overlap (no two legs in one place) and folds old contacts into their legs' evidence. */
class LastingMap
{
   public:
	struct TOptions
	{
		/** Legs within this distance (m) of a new contact, and tables with a corner that
		 *  close, are visited by the local anneal; legs within it plus a table diagonal and
		 *  two parent gates are on the board (dormant) as partners of new tables. */
		double visit_radius = 0.15;
		/** Explicit contacts a leg keeps (the sampler may still move them between legs);
		 *  older ones are folded into its evidence. */
		uint32_t contacts_per_leg = 6;
		/** Unexplained contacts kept within one leg width of each other; older ones are
		 *  forgotten (they never found a cause). */
		uint32_t unexplained_per_spot = 4;
		/** Legs merged after an insertion: those that overlap, and those whose rectangles
		 *  come within this distance (m) of each other (a leg mapped again beside itself by a
		 *  drifting pose; whisker-slam's particle maps, doc/slam.md "Legs mapped again beside
		 *  the first"). 0: only legs that overlap (eq. 16 made hard). */
		double leg_merge_gap = 0;
		/** Revisions after each insertion whose readings are looser than the legs' placement
		 *  (model sigma_r > sigma_corner: the very noisy sensor, doc/model.md "Two noises"):
		 *  each re-anneals, with the sampler's full schedule, the local problem around the
		 *  explicit contacts of the next leg in a round robin over the map's legs (in the
		 *  insertion order of their contacts), visiting every hypothesis within a table
		 *  diagonal plus a parent gate of them (not only within visit_radius), so that tables
		 *  assembled from neighbours' legs before the right legs were touched are taken apart
		 *  later (doc/map-plugin.md, "What it does", step 10). 0: never. */
		uint32_t noisy_revisions = 2;
		/** Report each table at the pose of its rigid fit to all its legs' contacts
		 *  (inference::fitRigidTable), refitted when its legs change; false: the model's own
		 *  table pose (legs loose at its corners, eq. 6). */
		bool rigid_pose = true;
		/** Sweeps annealed together: each sweep's contacts join the state at once (explicit,
		 *  unexplained), and their local anneal (with its revisions) runs when this many
		 *  sweeps with contacts are pending, or at annealPending(). 1: every sweep (the
		 *  pending contacts are invisible to the sweep likelihood until then; doc/map-plugin.md). */
		uint32_t batch_sweeps = 1;
		/** The local anneal's schedule (insertOpts local_*, doc/map-plugin.md): it starts
		 *  from the map as it was with the new contacts associated, not from an empty board,
		 *  so it runs cooler and shorter than a per-pose step. beta_end and the moves are the
		 *  sampler's. */
		struct TSchedule
		{
			double beta_start = 0.1;
			uint32_t temperatures = 8, sweeps_per_temperature = 1, coldest_sweeps = 4, polish_sweeps = 2;
			bool operator==(const TSchedule& o) const
			{
				return beta_start == o.beta_start && temperatures == o.temperatures &&
					   sweeps_per_temperature == o.sweeps_per_temperature && coldest_sweeps == o.coldest_sweeps &&
					   polish_sweeps == o.polish_sweeps;
			}
		} schedule;
	};

	/** What one insertion did. */
	struct TStats
	{
		uint32_t visited = 0, boardHypotheses = 0, boardContacts = 0;  ///< the insertion's local problem
		/** Moves proposed and accepted, by kind: the insertion's anneal and its revisions'. */
		std::array<uint32_t, inference::MOVE_COUNT> proposed{}, accepted{};
		std::vector<inference::MoveTally> moveTypes;  ///< the same per move type
		bool changed = false;  ///< the state was written (the sweep had contacts)
		uint32_t revisions = 0;  ///< older regions revised after the insertion (noisy_revisions)
		double initialLogPosterior = 0, logPosterior = 0;  ///< local problem: associated, annealed
	};

	void setOptions(const TOptions& o) { m_options = o; }
	const TOptions& options() const { return m_options; }

	/** Inserts the contacts of one sweep (world frame), scored with `model`, annealed with
	 *  `sampler`'s schedule from `seed` together with those of the sweeps pending before it
	 *  once TOptions::batch_sweeps sweeps are pending (until then: added, not annealed, the
	 *  stats empty). With `model.free_space`, walls pay the untouched swept cells of `grid`
	 *  (eq. 25; null: none), which must already hold this sweep. */
	TStats insert(
		const std::vector<obs::Shapelet>& contacts, const model::ModelParams& model,
		const inference::SamplerParams& sampler, uint64_t seed, const model::SweptGrid* grid = nullptr);
	/** Anneals the pending sweeps' contacts now (as insert() does when the batch is full);
	 *  empty stats when none are pending. */
	TStats annealPending(
		const model::ModelParams& model, const inference::SamplerParams& sampler, uint64_t seed,
		const model::SweptGrid* grid = nullptr);
	/** Sweeps inserted but not annealed yet, and the insertion number (Contact::seq) of their
	 *  first contact: the pending contacts are those from it on (serialized with the map). */
	uint32_t pendingSweeps() const { return m_pendingSweeps; }
	uint64_t pendingFrom() const { return m_pendingFrom; }
	void setPending(uint32_t sweeps, uint64_t fromSeq) { m_pendingSweeps = sweeps, m_pendingFrom = fromSeq; }

	/** The spread of table t's pose (doc/map-plugin.md, "Pose spread"): inference::rigidPoseSpread
	 *  from its rigid fit, under `model` with shaft noise on (as the reported pose is fitted),
	 *  seeded with `seed`. */
	inference::PoseSpread poseSpread(model::Id t, const model::ModelParams& model, uint64_t seed) const;

	const model::LastingState& state() const { return m_state; }
	model::LastingState& state() { return m_state; }
	/** The insertion number (LastingState::Contact::seq) the next revision starts its round
	 *  robin from (serialized with the map: content, not store ids, so a reload continues as
	 *  the original would). */
	uint64_t reviseSeq() const { return m_reviseSeq; }
	void setReviseSeq(uint64_t s) { m_reviseSeq = s; }
	void clear() { m_state.clear(), m_reviseSeq = 0, m_pendingSweeps = 0, m_pendingFrom = 0; }

   private:
	/** The local problem around ws.fresh (hypotheses within `visit` metres visited): extracted,
	 *  annealed with `sampler` (built once per model and schedule into `cache`, one of ws's
	 *  samplers), written back. */
	TStats solve(
		LastingWorkspace& ws, const model::ModelParams& model, const inference::SamplerParams& sampler, double visit,
		uint64_t seed, const model::SweptGrid* grid, std::unique_ptr<inference::BlackboardSampler>& cache);
	/** One revision (TOptions::noisy_revisions): the problem around the explicit contacts of
	 *  the leg holding the oldest explicit contact inserted at or after m_reviseSeq (from the
	 *  oldest again when none is), its figures into `out`; false when no leg holds a contact. */
	bool reviseNext(
		LastingWorkspace& ws, const model::ModelParams& model, const inference::SamplerParams& sampler, uint64_t seed,
		const model::SweptGrid* grid, TStats& out);
	/** The model the reported poses are fitted (and their spreads scored) with: `model` with
	 *  shaft noise on. */
	static model::ModelParams reportModel(const model::ModelParams& model);
	/** Existence of each table of `solved` (grown from `start`, the region's board): the
	 *  tables near a change scored again, by TableExistence or, with the sampler's
	 *  posterior_steps, by the posterior chain from `solved` (seeded from `seed`). ws.spread
	 *  gets each table's chain pose spread: the chain's for those it scored, the stored one for
	 *  the rest (none where TableExistence scored). */
	std::vector<double> existence(
		LastingWorkspace& ws, const model::Blackboard& start, const model::Blackboard& solved,
		const model::ModelParams& model, const inference::SamplerParams& sampler, uint64_t seed);
	/** Existence of each wall of `solved`: the logistic of its log-odds (model::logOddsWall). */
	static std::vector<double> wallExistence(const model::Blackboard& solved);
	/** Refits the reported pose of every table whose legs the last replace() may have changed:
	 *  the region's (but those in ws.carry, whose legs explain the same contacts as before:
	 *  they keep their pose), and those its legs stood under before (ws.refit) or stand under now. */
	void refitReported(LastingWorkspace& ws, const model::ModelParams& model);

	// The map's content only: the working memory of an insertion is the thread's
	// (LastingWorkspace), so a copy is the state and its options.
	model::LastingState m_state;
	TOptions m_options;
	uint64_t m_reviseSeq = 0;
	uint32_t m_pendingSweeps = 0;
	uint64_t m_pendingFrom = 0;
};
}  // namespace whiskermap::maps
