#pragma once
#include <whiskermap/inference/moves/MoveEntry.h>

#include <vector>

namespace whiskermap::inference::moves
{
/** The moves of the sampler, one line each, in the order a sweep offers them
 *  (doc/sampler.md, "Moves"). Adding a move: its class (a header in moves/) and one line in
 *  MoveRegistry.cpp. Owns the moves' scratch: one registry per sampler. */
class MoveRegistry
{
   public:
	explicit MoveRegistry(const model::ModelParams& p);

	const std::vector<MoveEntry>& entries() const { return m_entries; }

   private:
	std::vector<MoveEntry> m_entries;
};
}  // namespace whiskermap::inference::moves
