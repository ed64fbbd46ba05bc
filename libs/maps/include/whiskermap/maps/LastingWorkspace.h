#pragma once
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/PosteriorChain.h>
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/TableExistence.h>
#include <whiskermap/maps/LastingMap.h>
#include <whiskermap/model/LastingState.h>

#include <memory>
#include <utility>
#include <vector>

namespace whiskermap::maps
{
/** A lasting map's working memory for one insertion (LastingMap::insert): the samplers built
 *  for a model and schedule, the local problem, the existence scorer and the scratch lists.
 *  An insertion starts each of them afresh from the map's state and its seed, so nothing in
 *  it carries from one insertion to the next but allocated capacity; every lasting map on a
 *  thread therefore shares one (local()): a particle filter's hundred maps hold one working
 *  memory, not a hundred (doc/slam.md, "Memory"). */
struct LastingWorkspace
{
	/** This thread's workspace, with samplers for `model`, `sampler` and the local
	 *  `schedule` (built on first use, rebuilt when any of them changes). */
	static LastingWorkspace& local(
		const model::ModelParams& model, const inference::SamplerParams& sampler,
		const LastingMap::TOptions::TSchedule& schedule);

	/** The local schedule's sampler and the revisions' (the sampler's full schedule). */
	std::unique_ptr<inference::BlackboardSampler> sampler, reviser;
	std::unique_ptr<inference::PosteriorChain> posterior;  ///< with posterior_steps
	std::unique_ptr<model::LastingState::Region> region;
	inference::TableExistence existence;
	std::vector<model::Id> fresh, newTables, newLegs, refit, merged;  ///< fresh: the contacts the anneal explains
	std::vector<std::pair<model::Id, model::Table>> carry;
	std::vector<model::LastingState::ChainSpread> spread;  ///< existence()'s, by board id

   private:
	model::ModelParams m_model;
	inference::SamplerParams m_sampler;
	LastingMap::TOptions::TSchedule m_schedule;
};
}  // namespace whiskermap::maps
