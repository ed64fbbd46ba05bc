#include <whiskermap/maps/LastingWorkspace.h>

namespace whiskermap::maps
{
LastingWorkspace& LastingWorkspace::local(
	const model::ModelParams& model, const inference::SamplerParams& sampler,
	const LastingMap::TOptions::TSchedule& schedule)
{
	thread_local LastingWorkspace ws;
	if (!ws.m_built || !(ws.m_model == model) || !(ws.m_sampler == sampler) || !(ws.m_schedule == schedule))
	{
		ws.sampler.reset(), ws.reviser.reset(), ws.posterior.reset(), ws.region.reset();
		ws.m_model = model, ws.m_sampler = sampler, ws.m_schedule = schedule, ws.m_built = true;
	}
	return ws;
}
}  // namespace whiskermap::maps
