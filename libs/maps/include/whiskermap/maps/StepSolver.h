#pragma once
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/maps/TStepInput.h>

#include <memory>

namespace whiskermap::maps
{
/** Runs sampler steps, keeping one BlackboardSampler (and its buffers) for as long as the
 *  steps' model stays the same. A copy starts without a sampler: a step starts from an empty
 *  blackboard, so nothing but buffers is lost. One per thread. */
class StepSolver
{
   public:
	StepSolver() = default;
	StepSolver(const StepSolver&) {}
	StepSolver& operator=(const StepSolver&)
	{
		m_sampler.reset();
		return *this;
	}

	inference::StepResult solve(
		const TStepInput& in, const inference::SamplerParams& params, int snapshotTemperature = -1);

   private:
	std::unique_ptr<inference::BlackboardSampler> m_sampler;
	model::ModelParams m_model;
};
}  // namespace whiskermap::maps
