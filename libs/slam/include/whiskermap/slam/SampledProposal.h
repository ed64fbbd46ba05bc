#pragma once
#include <mrpt/maps/CMultiMetricMapPDF.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>

namespace whiskermap::slam
{
/** The prediction and update of one RBPF step: moves every particle by the odometry
 *  increment's motion model and weighs it by the sweep's likelihood in its own map.
 *
 *  With `samples` = 1 this is MRPT's standard proposal (pfStandardProposal: one motion sample
 *  per particle, its weight times the likelihood), draw for draw. With K > 1 each particle
 *  draws K motion samples x_k, keeps one with probability L_k / sum L (L_k the sweep's
 *  likelihood at x_k) and multiplies its weight by (1/K) sum L_k (eq. S1, doc/slam.md): a
 *  sampled approximation of the optimal proposal p(x | x_prev, z) whose weight is an unbiased
 *  estimate of p(z | x_prev, map), so the filter targets the same posterior while most
 *  particles land where the sweep fits their map. Weights are normalised afterwards (max 0),
 *  as CParticleFilter::executeOn does. Random draws come from MRPT's global generator. */
class SampledProposal
{
   public:
	explicit SampledProposal(unsigned samples);
	/** One step on every particle of `pdf`: appends the new pose to each robotPath and adds the
	 *  log weight. Throws core::Error when a likelihood is NaN, or when none of a particle's
	 *  samples has a finite one. */
	void apply(
		mrpt::maps::CMultiMetricMapPDF& pdf, const mrpt::obs::CActionRobotMovement2D& move,
		const mrpt::obs::CSensoryFrame& frame) const;
	unsigned samples() const { return m_samples; }

   private:
	unsigned m_samples;
};
}  // namespace whiskermap::slam
