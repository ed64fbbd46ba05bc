#include <whiskermap/maps/StepSolver.h>

namespace whiskermap::maps
{
inference::StepResult StepSolver::solve(
	const TStepInput& in, const inference::SamplerParams& params, int snapshotTemperature)
{
	if (!m_sampler || !(in.model == m_model))
	{
		m_sampler = std::make_unique<inference::BlackboardSampler>(in.model, params);
		m_model = in.model;
	}
	return m_sampler->step(in.memory, in.swept, in.seed, snapshotTemperature);
}
}  // namespace whiskermap::maps
