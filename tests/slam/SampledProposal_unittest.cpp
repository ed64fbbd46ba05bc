#include <gtest/gtest.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/slam/SampledProposal.h>
#include <whiskermap/obs/RawlogReader.h>

#include <memory>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
constexpr size_t MAPPED = 150;  // sweeps of the paper grid mapped at their true poses

/** Particles that all hold the map of the paper grid's first MAPPED sweeps (at the true
 *  poses) and stand at sweep MAPPED - 1's pose, ready to localise sweep MAPPED. */
class SampledProposalTest : public ::testing::Test
{
   protected:
	static void SetUpTestSuite()
	{
		s_sweeps = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog").sweeps;
		s_inits = maps::MapConfig::load(SRC + "/config/whisker-map.ini");
		s_map = std::make_unique<mrpt::maps::CMultiMetricMap>(s_inits);
		for (size_t i = 0; i < MAPPED; i++) s_map->insertObservation(*s_sweeps[i].obs, mrpt::poses::CPose3D(s_sweeps[i].robotPose));
	}
	static void TearDownTestSuite() { s_map.reset(); }

	std::unique_ptr<mrpt::maps::CMultiMetricMapPDF> particles(size_t n) const
	{
		mrpt::bayes::CParticleFilter::TParticleFilterOptions o;
		o.sampleSize = n;
		auto pdf = std::make_unique<mrpt::maps::CMultiMetricMapPDF>(o, s_inits, mrpt::maps::CMultiMetricMapPDF::TPredictionParams{});
		pdf->clear(mrpt::poses::CPose3D(from()));
		for (auto& p : pdf->m_particles)
		{
			p.d->mapTillNow.maps.clear();
			for (const auto& m : s_map->maps)
				p.d->mapTillNow.maps.push_back(std::dynamic_pointer_cast<mrpt::maps::CMetricMap>(m->duplicateGetSmartPtr()));
		}
		return pdf;
	}
	static mrpt::poses::CPose2D from() { return s_sweeps[MAPPED - 1].robotPose; }
	static mrpt::poses::CPose2D truth() { return s_sweeps[MAPPED].robotPose; }
	/** The true increment with a Gaussian motion model of `sigma` metres (and sigma / 0.1
	 *  radians) per step. */
	static mrpt::obs::CActionRobotMovement2D move(double sigma)
	{
		mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m;
		m.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
		m.gaussianModel = {0, 0, 0, 0, sigma, sigma};
		mrpt::obs::CActionRobotMovement2D a;
		a.computeFromOdometry(truth() - from(), m);
		return a;
	}
	static mrpt::obs::CSensoryFrame frame()
	{
		mrpt::obs::CSensoryFrame f;
		f.insert(s_sweeps[MAPPED].obs);
		return f;
	}
	static double meanError(const mrpt::maps::CMultiMetricMapPDF& pdf)
	{
		double sum = 0;
		for (const auto& p : pdf.m_particles)
			sum += mrpt::poses::CPose2D(mrpt::poses::CPose3D(p.d->robotPath.back())).distanceTo(truth());
		return sum / pdf.m_particles.size();
	}

	static inline std::vector<obs::RawlogReader::Sweep> s_sweeps;
	static inline mrpt::maps::TSetOfMetricMapInitializers s_inits;
	static inline std::unique_ptr<mrpt::maps::CMultiMetricMap> s_map;
};
}  // namespace

TEST_F(SampledProposalTest, OneSampleIsMrptsStandardProposalDrawForDraw)
{
	auto a = particles(8), b = particles(8);
	const auto m = move(0.03);
	mrpt::obs::CActionCollection actions;
	actions.insert(m);
	const auto f = frame();
	mrpt::bayes::CParticleFilter filter;
	filter.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
	filter.m_options.BETA = 0;
	mrpt::random::getRandomGenerator().randomize(5);
	filter.executeOn(*a, &actions, &f);
	mrpt::random::getRandomGenerator().randomize(5);
	slam::SampledProposal(1).apply(*b, m, f);
	bool weightsDiffer = false;
	for (size_t i = 0; i < a->particlesCount(); i++)
	{
		ASSERT_EQ(b->m_particles[i].d->robotPath.size(), 2u);
		const auto &pa = a->m_particles[i].d->robotPath.back(), &pb = b->m_particles[i].d->robotPath.back();
		EXPECT_EQ(pa.x, pb.x);
		EXPECT_EQ(pa.y, pb.y);
		EXPECT_EQ(pa.yaw, pb.yaw);
		EXPECT_EQ(a->getW(i), b->getW(i));
		weightsDiffer |= b->getW(i) < -1;
	}
	EXPECT_TRUE(weightsDiffer);  // the sweep tells these particles apart: the weights are tested
}

TEST_F(SampledProposalTest, ManySamplesLandWhereTheSweepFitsTheMap)
{
	// Motion noise of 5 cm (and 0.05 rad) a step: one motion sample lands 6.3 cm from the
	// truth on average; picking one of 30 by the sweep's likelihood brings that to 2.4 cm
	// (1.9-2.6 cm for the turns at sweeps 130-250 of this log).
	const auto m = move(0.05);
	const auto f = frame();
	auto one = particles(100), many = particles(100);
	mrpt::random::getRandomGenerator().randomize(3);
	slam::SampledProposal(1).apply(*one, m, f);
	slam::SampledProposal(30).apply(*many, m, f);
	EXPECT_GT(meanError(*one), 0.04);
	EXPECT_LT(meanError(*many), 0.5 * meanError(*one)) << meanError(*many) << " vs " << meanError(*one);
}

TEST_F(SampledProposalTest, WithoutMotionNoiseManySamplesWeighAsOne)
{
	// All K samples are the same pose x: eq. S1's weight (1/K) sum L_k is L(x), as one sample's.
	const auto m = move(0);
	const auto f = frame();
	auto one = particles(3), many = particles(3);
	// Particles at different poses, so that their weights differ.
	for (auto* pdf : {one.get(), many.get()})
		for (size_t i = 0; i < 3; i++) pdf->m_particles[i].d->robotPath.back().x += 0.02 * double(i);
	slam::SampledProposal(1).apply(*one, m, f);
	slam::SampledProposal(7).apply(*many, m, f);
	for (size_t i = 0; i < 3; i++)
	{
		EXPECT_NEAR(one->getW(i), many->getW(i), 1e-9);
		EXPECT_EQ(one->m_particles[i].d->robotPath.back().x, many->m_particles[i].d->robotPath.back().x);
	}
	EXPECT_LT(one->getW(2), -1);  // 4 cm off: the weights are tested
}

TEST(SampledProposal, RefusesZeroSamples) { EXPECT_THROW(slam::SampledProposal(0), std::exception); }
