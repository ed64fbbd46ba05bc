#pragma once
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/SamplerRandom.h>
#include <whiskermap/inference/StepResult.h>
#include <whiskermap/inference/moves/Proposal.h>
#include <whiskermap/model/Blackboard.h>

#include <cmath>
#include <vector>

namespace whiskermap::inference
{
class Acceptance;
}

namespace whiskermap::inference::moves
{
/** What a move sees of the sampler: the board, the parameters, the random numbers, the
 *  temperature and the acceptance (which the sampler owns), plus the leg geometry several
 *  moves share (placement of a new leg, closed-form refit). Not thread-safe. */
class MoveContext
{
   public:
	MoveContext(
		model::Blackboard& board, const model::ModelParams& modelParams, const SamplerParams& samplerParams,
		SamplerRandom& random,
		const Acceptance& acceptance);

	model::Blackboard& bb;
	const model::ModelParams& mp;  ///< the model's parameters
	const SamplerParams& sp;  ///< the sampler's parameters
	SamplerRandom& rng;
	double beta = 1;  ///< inverse temperature; inf: the greedy polish
	bool searchPoses = false;  ///< the polish's last sweep also searches leg poses
	StepResult* result = nullptr;  ///< where proposals and acceptances are counted
	/** The registry line whose move is visiting (its tally in result->moveTypes), or NO_ENTRY. */
	size_t entry = NO_ENTRY;
	static constexpr size_t NO_ENTRY = ~size_t{0};

	bool greedy() const { return std::isinf(beta); }

	/** Counts `p` and judges it with the sampler's acceptance at `beta`. */
	bool accept(const Proposal& p);
	/** Counts a move of kind `m` judged elsewhere (the polish's pose search). */
	void count(Move m, bool accepted);
	/** Lets the sampler judge move `move`'s proposal `p`, then finishes the move (keeps or
	 *  undoes it). Returns the decision. */
	template <class M>
	bool judge(M& move, const Proposal& p)
	{
		const bool yes = accept(p);
		move.finish(*this, yes);
		return yes;
	}

	/** A new free leg for shapelet s, with s on its face (Q(pa(S)), doc/sampler.md). */
	model::Leg newLegFor(size_t s);
	/** Where along its face the contact of shapelet s lies, from the leg centre, when another
	 *  shapelet nearby fixes it (adjacent faces of one leg): true and `offset`; else false
	 *  (the offset is then uniform on the face). Draws nothing. */
	bool adjacentFaceOffset(size_t s, double& offset) const;
	/** Legs whose perimeter is within the parent gate of shapelet `s`. */
	void legsNearShapelet(size_t s, std::vector<model::Id>& out) const;
	/** Closed-form pose (PoseFit.h) of leg `l` for its contacts and, with `t`, the corner of
	 *  `t` nearest to it. False if there is nothing to fit or the fit leaves a contact or the
	 *  corner outside the parent gate. */
	bool fittedLeg(model::Id l, const model::Table* t, model::Leg& out);
	/** Moves leg l to its fitted pose (if valid: returns true) and adds the change of logJoint
	 *  to `gain` (local, eq. 20 before and after). */
	bool refitInPlace(model::Id l, double& gain);
	/** True if refitInPlace would leave leg l where it is (to 1e-12; an invalid fit leaves it):
	 *  then a move that refits l can be undone by a move that refits it back. */
	bool atFit(model::Id l);

   private:
	const Acceptance& m_acceptance;
	std::vector<const obs::Shapelet*> m_contacts;
};
}  // namespace whiskermap::inference::moves
