#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <functional>

namespace whiskermap::inference::moves
{
/** Which hypotheses a registered move visits in a sweep. */
enum class Target : uint8_t
{
	Shapelet,  ///< every shapelet without a leg (priming)
	Table,
	Leg,
	Wall,  ///< every wall (doc/sampler.md, "Walls")
};

/** When a move is offered at a visited hypothesis, from the draw u ~ U(0, 1) per hypothesis
 *  and the thresholds r1..r4 (SamplerParams). The greedy polish offers every move but the
 *  pose search, which it offers on its last sweep only; it alone offers the Polish slots. */
enum class Slot : uint8_t
{
	Death,  ///< u < r1
	NewParent,  ///< r1 <= u < r2
	Child,  ///< r2 <= u < r3
	Refit,  ///< r3 <= u < r4
	Parent,  ///< u >= r4
	Always,  ///< every visit (priming)
	PolishLastSweep,  ///< only in the polish's last sweep
	/** Every polish sweep but the last: a table born in the last would get no invented legs
	 *  (a sweep visits the tables before the legs). */
	PolishButLast,
};

/** One line of the MoveRegistry: a move offered to the hypotheses of `target` in `slot`.
 *  `visit` proposes (drawing its own choices from ctx.rng), lets the sampler's acceptance
 *  judge the Proposal (ctx.judge) and finishes the move. */
struct MoveEntry
{
	const char* name;
	Target target;
	Slot slot;
	int polishRepeats;  ///< offers per hypothesis in a polish sweep (a table misses up to 3 legs)
	std::function<void(MoveContext&, model::Id)> visit;

	/** True if this move is offered at draw u in ctx's sweep. */
	bool offered(const MoveContext& ctx, double u) const;
};
}  // namespace whiskermap::inference::moves
