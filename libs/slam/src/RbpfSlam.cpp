#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/slam/RbpfSlam.h>

#include <chrono>

namespace whiskermap::slam
{
namespace
{
mrpt::slam::CMetricMapBuilderRBPF::TConstructionOptions builderOptions(
	const TSlamParams& p, const mrpt::maps::TSetOfMetricMapInitializers& maps)
{
	mrpt::slam::CMetricMapBuilderRBPF::TConstructionOptions o;
	o.mapsInitializers = maps;
	o.PF_options.sampleSize = p.particles;
	o.PF_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
	o.PF_options.resamplingMethod = p.resampling;
	o.PF_options.adaptiveSampleSize = false;
	o.PF_options.BETA = 0;  // the filter never resamples by itself: step() does, after recording the ESS
	o.insertionLinDistance = o.insertionAngDistance = 0;
	o.localizeLinDistance = o.localizeAngDistance = 0;
	o.verbosity_level = mrpt::system::LVL_ERROR;
	return o;
}
}  // namespace

RbpfSlam::RbpfSlam(const TSlamParams& params, const mrpt::maps::TSetOfMetricMapInitializers& maps)
	: m_params(params), m_builder(builderOptions(params, maps))
{
	mrpt::random::getRandomGenerator().randomize(params.seed);
	m_builder.options.debugForceInsertion = true;  // every sweep is localised and inserted
	m_builder.setVerbosityLevel(mrpt::system::LVL_ERROR);
}

void RbpfSlam::step(const obs::RawlogReader::Sweep& sweep)
{
	const auto t0 = std::chrono::steady_clock::now();
	if (!m_lastOdometry)
	{
		// Known start: every particle at the first odometry pose, with an empty map.
		const mrpt::poses::CPosePDFGaussian start(sweep.robotPose);
		m_builder.initialize(mrpt::maps::CSimpleMap(), &start);
	}
	const mrpt::poses::CPose2D increment = sweep.robotPose - (m_lastOdometry ? *m_lastOdometry : sweep.robotPose);
	m_lastOdometry = sweep.robotPose;
	auto model = m_params.motion.motionModel(increment);
	auto& g = model.gaussianModel;
	g.a1 *= m_params.motion_noise_scale, g.a2 *= m_params.motion_noise_scale;
	g.a3 *= m_params.motion_noise_scale, g.a4 *= m_params.motion_noise_scale;
	mrpt::obs::CActionRobotMovement2D move;
	move.timestamp = sweep.obs->timestamp;
	move.computeFromOdometry(increment, model);
	mrpt::obs::CActionCollection actions;
	actions.insert(move);
	mrpt::obs::CSensoryFrame frame;
	frame.insert(sweep.obs);

	// Resampling decided at the previous step happens now, before moving the particles: the
	// weights after the last sweep stay as the filter left them, so the best particle at the
	// end is the most probable one, not a pick among equal weights.
	auto& pdf = m_builder.mapPDF;
	if (m_resamplePending)
	{
		mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
		pf.resamplingMethod = m_params.resampling;
		pdf.performResampling(pf);
	}
	m_builder.processActionObservation(actions, frame);
	TStep s;
	s.ess = pdf.ESS();
	s.resampled = m_resamplePending = s.ess < m_params.resample_ess;
	s.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	m_steps.push_back(s);
}

size_t RbpfSlam::bestParticle() const
{
	const auto& pdf = m_builder.mapPDF;
	size_t best = 0;
	for (size_t i = 1; i < pdf.particlesCount(); i++)
		if (pdf.getW(i) > pdf.getW(best)) best = i;
	return best;
}

std::vector<mrpt::poses::CPose2D> RbpfSlam::bestPath() const
{
	std::deque<mrpt::math::TPose3D> path;
	m_builder.mapPDF.getPath(bestParticle(), path);
	// The path starts with the initial pose, then one pose per step.
	if (path.size() != m_steps.size() + 1)
		throw core::Error(
			"RBPF: the best particle's path has " + std::to_string(path.size()) + " poses for " +
			std::to_string(m_steps.size()) + " sweeps");
	std::vector<mrpt::poses::CPose2D> out;
	for (size_t i = 1; i < path.size(); i++) out.emplace_back(path[i].x, path[i].y, path[i].yaw);
	return out;
}

const maps::CHierarchicalObjectMap& RbpfSlam::bestMap() const
{
	if (m_steps.empty()) throw core::Error("RBPF: no sweep processed yet");
	const auto map = m_builder.mapPDF.m_particles[bestParticle()].d->mapTillNow.mapByClass<maps::CHierarchicalObjectMap>();
	if (!map) throw core::Error("RBPF: the particles hold no hierarchicalObjectMap");
	return *map;
}
}  // namespace whiskermap::slam
