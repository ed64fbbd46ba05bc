#include <mrpt/poses/CPoseRandomSampler.h>
#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/slam/SampledProposal.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace whiskermap::slam
{
SampledProposal::SampledProposal(unsigned samples) : m_samples(samples)
{
	if (samples < 1) throw core::Error("RBPF proposal: at least one motion sample per particle");
}

void SampledProposal::apply(
	mrpt::maps::CMultiMetricMapPDF& pdf, const mrpt::obs::CActionRobotMovement2D& move,
	const mrpt::obs::CSensoryFrame& frame) const
{
	mrpt::poses::CPoseRandomSampler drawer;
	drawer.setPosePDF(*move.poseChange);
	auto& particles = pdf.m_particles;
	// MRPT's standard proposal draws every particle's increment first, then weighs: kept
	// for K = 1, so that the draws are MRPT's to the last bit.
	std::vector<mrpt::poses::CPose3D> drawn(particles.size() * m_samples);
	std::vector<double> logL(m_samples);
	mrpt::poses::CPose3D increment;
	for (size_t i = 0; i < particles.size(); i++)
	{
		const mrpt::poses::CPose3D from(particles[i].d->robotPath.back());
		for (unsigned k = 0; k < m_samples; k++)
		{
			drawer.drawSample(increment);
			drawn[i * m_samples + k] = from + increment;
		}
	}
	auto& random = mrpt::random::getRandomGenerator();
	for (size_t i = 0; i < particles.size(); i++)
	{
		auto& map = particles[i].d->mapTillNow;
		const auto* x = &drawn[i * m_samples];
		for (unsigned k = 0; k < m_samples; k++)
		{
			logL[k] = 0;
			for (const auto& o : frame) logL[k] += map.computeObservationLikelihood(*o, x[k]);
			if (std::isnan(logL[k])) throw core::Error("RBPF proposal: the sweep likelihood is NaN");
		}
		// Some sample must be possible (MRPT's standard proposal asserts a finite likelihood too).
		const double top = *std::max_element(logL.begin(), logL.end());
		if (!std::isfinite(top)) throw core::Error("RBPF proposal: the sweep likelihood is not finite");
		unsigned pick = 0;
		if (m_samples == 1)
			particles[i].log_w += logL[0];
		else
		{
			// eq. S1: x ~ L_k / sum L, log w += log((1/K) sum L_k)
			double sum = 0;
			for (double l : logL) sum += std::exp(l - top);
			double u = random.drawUniform(0.0, sum);
			for (pick = 0; pick + 1 < m_samples; pick++)
				if ((u -= std::exp(logL[pick] - top)) < 0) break;
			particles[i].log_w += top + std::log(sum / m_samples);
		}
		particles[i].d->robotPath.push_back(x[pick].asTPose());
	}
	pdf.normalizeWeights();
}
}  // namespace whiskermap::slam
