#pragma once
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/SamplerRandom.h>
#include <whiskermap/inference/StepResult.h>
#include <whiskermap/inference/moves/Proposal.h>
#include <whiskermap/model/Blackboard.h>

#include <cmath>
#include <functional>
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
	/** anneal(): an insertion into the lasting map, not a per-pose step (the polish's sliding
	 *  table and contact exchange are the step's only: doc/sampler.md, "Polish moves"). */
	bool annealing = false;
	StepResult* result = nullptr;  ///< where proposals and acceptances are counted
	/** The registry line whose move is visiting (its tally in result->moveTypes), or NO_ENTRY. */
	size_t entry = NO_ENTRY;
	static constexpr size_t NO_ENTRY = ~size_t{0};

	/** Benchmarks (proposals until the MAP): called after every change the sampler keeps. */
	std::function<void(const model::Blackboard&, const StepResult&)> watcher;

	bool greedy() const { return std::isinf(beta); }
	/** The broad baseline (SamplerParams::proposals, doc/sampler.md "Broad proposals"). */
	bool broad() const { return sp.proposals == Proposals::Broad; }
	/** Refits draw about their fits (doc/sampler.md, "Stochastic refits"): under the
	 *  reversible-jump acceptance at finite beta, with data-driven proposals. */
	bool stochasticRefits() const
	{
		return sp.acceptance == AcceptanceRule::ReversibleJump && !greedy() && !broad();
	}
	/** Tells the watcher (if any) that the board changed and the change stays. */
	void changed()
	{
		if (watcher) watcher(bb, *result);
	}

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
		if (yes) changed();
		return yes;
	}

	/** A new free leg for shapelet s, with s on its face (Q(pa(S)), doc/sampler.md); broad:
	 *  its centre uniform within one leg width of s, its yaw uniform. */
	model::Leg newLegFor(size_t s);
	/** Where along its face the contact of shapelet s lies, from the leg centre, when another
	 *  shapelet nearby fixes it (adjacent faces of one leg): true and `offset`; else false
	 *  (the offset is then uniform on the face). Draws nothing. */
	bool adjacentFaceOffset(size_t s, double& offset) const;
	/** Legs whose perimeter is within the parent gate of shapelet `s`. */
	void legsNearShapelet(size_t s, std::vector<model::Id>& out) const;
	/** Closed-form pose (PoseFit.h) of leg `l` for its contacts and, with `t`, the corner of
	 *  `t` nearest to it (broad: a randomWalk step from its pose). False if there is nothing
	 *  to fit or the fit leaves a contact or the corner outside the parent gate. */
	bool fittedLeg(model::Id l, const model::Table* t, model::Leg& out);
	/** Moves leg l to its fitted pose (if valid: returns true) and adds the change of logJoint
	 *  to `gain` (local, eq. 20 before and after). */
	bool refitInPlace(model::Id l, double& gain);
	/** The stochastic refit of leg l (stochasticRefits()): its fit (fittedLeg, with its
	 *  parent's corner) plus N(0, leg_position_noise^2) per axis and N(0, leg_angle_noise^2)
	 *  in yaw. Adds the change of logJoint to `gain` (eq. 20) and the draw's log density to
	 *  `logForward`; false (board unchanged) if the leg has no valid fit. */
	bool drawRefit(model::Id l, double& gain, double& logForward);
	/** log density with which drawRefit(l) on the board as it is now would draw `pose`
	 *  (-inf without a valid fit): the reverse of a stochastic refit. */
	double logRefitTo(model::Id l, const model::Leg& pose);
	/** log density of `leg` drawn about `fit` by a stochastic refit (texture and size: the
	 *  fit's, else -inf); a zero noise makes its coordinate a point mass (0 at the fit). */
	double logDrawnAbout(const model::Leg& leg, const model::Leg& fit) const;
	/** A stochastic refit's draw of a table about `fit`: x, y + N(0, leg_position_noise^2),
	 *  yaw + N(0, tableAngleNoise^2), and with `size` its length and width offsets +
	 *  N(0, leg_position_noise^2) each (else the fit's). */
	model::Table drawnTable(const model::Table& fit, bool size);
	/** The yaw noise of a table's draw: leg_position_noise over its half-diagonal, so that its
	 *  corners move about as far as its centre (leg_angle_noise, a leg's, would move a metre
	 *  table's corners ten times further). */
	double tableAngleNoise(const model::Table& t) const;
	/** log density of drawnTable(fit, size) drawing `table`: -inf if its class, leg width or
	 *  texture (and without `size`, its size) differ from the fit's. Yaws are compared modulo
	 *  pi (pi/2 for a square table): turned by that, a table is the same table. */
	double logTableDrawnAbout(const model::Table& table, const model::Table& fit, bool size) const;
	/** log N(d; 0, sigma^2) of a stochastic refit's offset d; sigma = 0: a point mass at 0
	 *  (0 there, -inf elsewhere; never NaN, which an acceptance would take for 1). */
	static double logNoise(double d, double sigma);
	/** True if refitInPlace would leave leg l where it is (to 1e-12; an invalid fit leaves it):
	 *  then a move that refits l can be undone by a move that refits it back. Broad: false
	 *  (a random-walk step always moves). */
	bool atFit(model::Id l);
	/** The broad proposals' symmetric random-walk step of a pose: with probability 1/2 a
	 *  small step (N(0, leg_position_noise^2) per axis, N(0, leg_angle_noise^2) in yaw), else
	 *  one ten times larger. */
	void randomWalk(double& x, double& y, double& theta);

   private:
	/** fittedLeg(l) with the table l is a leg of (if any). */
	bool fitUnderParent(model::Id l, model::Leg& out);
	/** Moves leg l to `to`, adding the change of its eq. 20 log-odds to `gain`. */
	void moveLeg(model::Id l, const model::Leg& to, double& gain);

	const Acceptance& m_acceptance;
	std::vector<const obs::Shapelet*> m_contacts;
};
}  // namespace whiskermap::inference::moves
