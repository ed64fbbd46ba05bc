#include <mrpt/bayes/CParticleFilterCapable.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/slam/RbpfSlam.h>

#include <algorithm>
#include <chrono>
#include <type_traits>

namespace whiskermap::slam
{
namespace
{
mrpt::bayes::CParticleFilter::TParticleFilterOptions filterOptions(const TSlamParams& p)
{
	mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
	o.sampleSize = p.filterParticles();
	o.resamplingMethod = p.resampling;
	o.adaptiveSampleSize = false;
	return o;
}

mrpt::math::TPose2D latest(const mrpt::maps::CRBPFParticleData& d)
{
	const auto& p = d.robotPath.back();
	return {p.x, p.y, p.yaw};
}
}  // namespace

RbpfSlam::RbpfSlam(const TSlamParams& params, const mrpt::maps::TSetOfMetricMapInitializers& maps)
	: m_params(params), m_pdf(filterOptions(params), maps, {}), m_proposal(params.proposal_samples)
{
	mrpt::random::getRandomGenerator().randomize(params.seed);
}

void RbpfSlam::resample()
{
	// CParticleFilterCapable::performResampling, with the surviving indexes kept for the
	// paths, and equal weights after it: a copy stands for its share of its parent's weight
	// by being a copy. (MRPT 2.5.8's performResampling leaves the copies with their parents'
	// weights when the particle count does not change: its loop that sets them equal runs to
	// out_particle_count, which is then 0. The parents' weights then count twice, once in
	// the number of copies and once in their weights.)
	std::vector<double> logW(m_pdf.particlesCount());
	for (size_t i = 0; i < logW.size(); i++) logW[i] = m_pdf.getW(i);
	std::vector<size_t> parents;
	mrpt::bayes::CParticleFilterCapable::computeResampling(m_params.resampling, logW, parents);
	std::sort(parents.begin(), parents.end());
	// CParticleFilterDataImpl::performSubstitution's order and reuse (a parent's first copy
	// takes its data), but each further copy's maps are cloned (their copy constructors:
	// CHierarchicalObjectMap shares its swept grid's chunks) instead of MRPT's
	// CMultiMetricMap copy, a serialization round trip of every map (about 30 times slower:
	// doc/slam.md, "Memory").
	auto& particles = m_pdf.m_particles;
	std::remove_reference_t<decltype(particles)> next(parents.size());
	std::vector<long> taken(particles.size(), -1);  // where a parent's data went in `next`
	for (size_t i = 0; i < parents.size(); i++)
	{
		const size_t k = parents[i];
		if (taken[k] < 0)
		{
			next[i].d = std::move(particles[k].d);
			taken[k] = static_cast<long>(i);
			continue;
		}
		const auto& from = *next[static_cast<size_t>(taken[k])].d;
		auto* copy = new mrpt::maps::CRBPFParticleData();
		copy->robotPath = from.robotPath;
		for (const auto& m : from.mapTillNow.maps)
			copy->mapTillNow.maps.push_back(std::dynamic_pointer_cast<mrpt::maps::CMetricMap>(m->duplicateGetSmartPtr()));
		next[i].d.reset(copy);
	}
	particles = std::move(next);
	for (size_t i = 0; i < m_pdf.particlesCount(); i++) m_pdf.setW(i, 0);
	m_paths.resample(parents);
	m_resamplePending = false;
}

const RbpfSlam::TStep& RbpfSlam::step(const obs::RawlogReader::Sweep& sweep)
{
	const auto t0 = std::chrono::steady_clock::now();
	if (!m_lastOdometry)
	{
		// Known start: every particle at the first odometry pose, with an empty map.
		m_pdf.clear(mrpt::poses::CPose3D(sweep.robotPose));
		m_paths.reset(m_pdf.particlesCount(), sweep.robotPose.asTPose());
	}
	const mrpt::poses::CPose2D increment = sweep.robotPose - (m_lastOdometry ? *m_lastOdometry : sweep.robotPose);
	m_lastOdometry = sweep.robotPose;
	const auto model = m_params.motionModel(increment);
	// The increment as CMetricMapBuilderRBPF accumulates it (composed onto a zero CPose3D),
	// so that the draws are the builder's to the last bit.
	mrpt::poses::CPose3D accumulated;
	accumulated += mrpt::poses::CPose3D(increment);
	mrpt::obs::CActionRobotMovement2D move;
	move.timestamp = sweep.obs->timestamp;
	move.computeFromOdometry(mrpt::poses::CPose2D(accumulated), model);
	mrpt::obs::CSensoryFrame frame;
	frame.insert(sweep.obs);

	// Resampling decided at the previous step happens now, before moving the particles: the
	// weights after the last sweep stay as the filter left them, so the best particle at the
	// end is the most probable one, not a pick among equal weights.
	if (m_resamplePending) resample();
	m_proposal.apply(m_pdf, move, frame);
	for (size_t i = 0; i < m_pdf.particlesCount(); i++)
	{
		auto& d = *m_pdf.m_particles[i].d;
		frame.insertObservationsInto(d.mapTillNow, mrpt::poses::CPose3D(d.robotPath.back()));
		d.mapTillNow.auxParticleFilterCleanUp();
		m_paths.extend(i, latest(d));
		d.robotPath.erase(d.robotPath.begin(), d.robotPath.end() - 1);  // the filter needs the latest pose only
	}
	m_last.ess = m_pdf.ESS();
	m_last.resampled = m_resamplePending = m_last.ess < m_params.resample_ess;
	m_last.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	m_stepCount++;
	return m_last;
}

const RbpfSlam::TStep& RbpfSlam::lastStep() const
{
	if (!m_stepCount) throw core::Error("RBPF: no sweep processed yet");
	return m_last;
}

size_t RbpfSlam::settle(const std::function<void(const mrpt::poses::CPose2D&)>& sink)
{
	if (!m_stepCount) return 0;
	if (m_paths.nodes() > m_pathLimit)
		m_paths.mergeOlderThan(bestParticle(), std::max<size_t>(1, m_pathLimit / (4 * m_pdf.particlesCount())));
	else if (m_paths.nodes() < m_settleAt)
		return 0;
	// The first pose of the tree is the start, not a sweep's: not handed over.
	const size_t before = settledSweeps();
	bool start = m_paths.settled() == 0;
	m_paths.settle([&](const mrpt::math::TPose2D& p) {
		if (!start) sink(mrpt::poses::CPose2D(p));
		start = false;
	});
	m_settleAt = 2 * m_paths.nodes() + 1024;
	return settledSweeps() - before;
}

size_t RbpfSlam::settledSweeps() const { return m_paths.settled() > 0 ? m_paths.settled() - 1 : 0; }

size_t RbpfSlam::bestParticle() const
{
	size_t best = 0;
	for (size_t i = 1; i < m_pdf.particlesCount(); i++)
		if (m_pdf.getW(i) > m_pdf.getW(best)) best = i;
	return best;
}

std::vector<mrpt::poses::CPose2D> RbpfSlam::bestPath() const
{
	const auto path = m_paths.path(bestParticle());
	// The tree starts with the initial pose, then one pose per step; settle() takes the oldest.
	const size_t skip = m_paths.settled() == 0 ? 1 : 0;
	if (settledSweeps() + path.size() - skip != m_stepCount)
		throw core::Error(
			"RBPF: the best particle's path has " + std::to_string(path.size()) + " poses for " +
			std::to_string(m_stepCount - settledSweeps()) + " sweeps");
	std::vector<mrpt::poses::CPose2D> out;
	for (size_t i = skip; i < path.size(); i++) out.emplace_back(path[i]);
	return out;
}

RbpfSlam::TMapTotals RbpfSlam::mapTotals() const
{
	TMapTotals t;
	for (const auto& p : m_pdf.m_particles)
	{
		const auto map = p.d->mapTillNow.mapByClass<maps::CHierarchicalObjectMap>();
		if (!map) continue;
		const auto& s = map->lastingMap().state();
		t.tables += s.tableCount(), t.legs += s.legCount(), t.walls += s.walls().size();
		for (model::Id l = 0; l < s.legIdBound(); l++) t.legsWithoutTable += s.hasLeg(l) && s.leg(l).parent == model::NONE;
		t.legsBeside += s.legsBeside(BESIDE);
		for (model::Id c = 0; c < s.contactIdBound(); c++)
			if (s.hasContact(c)) (s.contact(c).leg == model::NONE ? t.unexplained : t.explained)++;
		t.sweptChunks += map->sweptGrid().chunkCount(), t.sharedChunks += map->sweptGrid().sharedChunks();
		const auto sharing = s.sharing();
		t.lastingChunks += sharing.chunks, t.lastingShared += sharing.shared;
	}
	return t;
}

const maps::CHierarchicalObjectMap& RbpfSlam::bestMap() const
{
	if (!m_stepCount) throw core::Error("RBPF: no sweep processed yet");
	const auto map = m_pdf.m_particles[bestParticle()].d->mapTillNow.mapByClass<maps::CHierarchicalObjectMap>();
	if (!map) throw core::Error("RBPF: the particles hold no hierarchicalObjectMap");
	return *map;
}
}  // namespace whiskermap::slam
