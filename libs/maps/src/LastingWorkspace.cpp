#include <whiskermap/maps/LastingWorkspace.h>

namespace whiskermap::maps
{
LastingWorkspace& LastingWorkspace::local(
	const model::ModelParams& model, const inference::SamplerParams& sampler,
	const LastingMap::TOptions::TSchedule& schedule)
{
	thread_local LastingWorkspace ws;
	// Nothing is built until first used, so a fresh workspace needs no reset whatever its key.
	if (!(ws.m_model == model) || !(ws.m_sampler == sampler) || !(ws.m_schedule == schedule))
	{
		ws.sampler.reset(), ws.reviser.reset(), ws.posterior.reset(), ws.region.reset();
		ws.m_model = model, ws.m_sampler = sampler, ws.m_schedule = schedule;
	}
	return ws;
}
}  // namespace whiskermap::maps
