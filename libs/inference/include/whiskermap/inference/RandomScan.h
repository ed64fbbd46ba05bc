#pragma once
#include <whiskermap/inference/moves/MoveContext.h>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace whiskermap::inference
{
/** One move of a random-scan schedule (doc/sampler.md, "Random scan"): `propose` draws its
 *  own target and change and returns the Proposal with the probabilities of those draws in
 *  logForward and, for the reverse move from the new board, in logReverse (nullopt: nothing
 *  proposed, the chain stays); `finish` keeps or undoes it. `reverse` is the index of the
 *  move that proposes the way back (itself for self-reverse moves). */
struct ScanMove
{
	std::string name;
	double weight = 1;  ///< chosen with probability weight / (sum of weights)
	size_t reverse = 0;
	std::function<std::optional<moves::Proposal>(moves::MoveContext&)> propose;
	std::function<void(moves::MoveContext&, bool)> finish;
};

/** A random-scan schedule for the reversible-jump acceptance: each step draws one move with
 *  its fixed probability and adds that probability to the Proposal's densities (log pi_m to
 *  logForward, log pi_reverse(m) to logReverse), so that the acceptance (ctx's, at ctx.beta)
 *  sees the whole proposal density q(new | old) and q(old | new). With exact moves this is a
 *  Metropolis-Hastings-Green chain whose stationary distribution is P^beta (tested:
 *  StationaryDistribution_unittest). */
class RandomScan
{
   public:
	/** Adds a move; returns its index. */
	size_t add(ScanMove m);
	std::vector<ScanMove>& moves() { return m_moves; }
	const std::vector<ScanMove>& moves() const { return m_moves; }

	/** One step: draws a move, lets it propose, judges and finishes it. Returns the move's
	 *  index. */
	size_t step(moves::MoveContext& ctx);

	/** Proposals (nullopt excluded) and acceptances per move. */
	const std::vector<long>& proposed() const { return m_proposed; }
	const std::vector<long>& accepted() const { return m_accepted; }

   private:
	std::vector<ScanMove> m_moves;
	std::vector<long> m_proposed, m_accepted;
};
}  // namespace whiskermap::inference
