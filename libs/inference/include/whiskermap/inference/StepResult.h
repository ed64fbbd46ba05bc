#pragma once
#include <whiskermap/model/HypothesisSet.h>

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace whiskermap::inference
{
/** The move types of Algorithm 1, for counting. */
enum class Move : uint8_t
{
	Priming,  ///< a leg for a shapelet without one (new, or an existing one nearby)
	Death,  ///< remove a hypothesis
	Reparent,  ///< replace a leg's parent table (or drop it)
	Child,  ///< a missing leg at a table's empty corner; a nearby shapelet for a leg
	Parent,  ///< a new table with the leg at one of its corners
	Refit,  ///< a leg or table moved onto its closed-form fit (doc/sampler.md)
};
constexpr size_t MOVE_COUNT = 6;

/** Proposals and acceptances of one move type (a line of the sampler's MoveRegistry). */
struct MoveTally
{
	std::string name;  ///< the registry's name ("table for leg", "leg refit", ...)
	uint64_t proposed = 0, accepted = 0;
};

/** Adds `from`'s tallies to `into`'s by name (appending names `into` lacks, in `from`'s order). */
void addTallies(std::vector<MoveTally>& into, const std::vector<MoveTally>& from);

/** Adds the move counts of `from` (anything with `proposed` and `accepted` per kind of move
 *  and `moveTypes`: a StepResult, a lasting insertion's figures) to running totals. */
template <class Counts, class From>
void addMoveCounts(Counts& proposed, Counts& accepted, std::vector<MoveTally>& types, const From& from)
{
	for (size_t k = 0; k < MOVE_COUNT; k++) proposed[k] += from.proposed[k], accepted[k] += from.accepted[k];
	addTallies(types, from.moveTypes);
}

/** What one time step of the sampler found. */
struct StepResult
{
	/** The MAP blackboard: the best (by log posterior) seen at the coldest temperature.
	 *  Its tables are the answer of eq. 18; legs and shapelet links come with it. */
	model::HypothesisSet map;
	double logPosterior = -std::numeric_limits<double>::infinity();  ///< logJoint of `map`
	/** anneal(): logJoint of the starting board once the new contacts were associated. */
	double initialLogPosterior = -std::numeric_limits<double>::infinity();

	std::array<uint32_t, MOVE_COUNT> proposed{};  ///< indexed by Move
	std::array<uint32_t, MOVE_COUNT> accepted{};
	/** The same counts per move type, in the registry's order (doc/sampler.md, "Moves"). */
	std::vector<MoveTally> moveTypes;
	/** Leg poses the polish's pose search scored (each of its searches counts once above). */
	uint64_t poseEvaluations = 0;
	/** The blackboard after the requested temperature index (figs. 1-2), if asked for. */
	std::optional<model::HypothesisSet> snapshot;

	uint32_t proposedOf(Move m) const { return proposed[static_cast<size_t>(m)]; }
	uint32_t acceptedOf(Move m) const { return accepted[static_cast<size_t>(m)]; }
};
}  // namespace whiskermap::inference
