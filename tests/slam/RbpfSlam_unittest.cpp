#include <gtest/gtest.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/math/wrap2pi.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/slam/RbpfSlam.h>

#include "../TempDirTest.h"

#include <algorithm>
#include <fstream>
#include <tuple>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
const std::string SLAM_INI = SRC + "/config/whisker-slam.ini";

/** The first `n` sweeps of the shipped default-odometry paper-arena SLAM log. */
std::vector<obs::RawlogReader::Sweep> firstSweeps(size_t n)
{
	auto sweeps = obs::RawlogReader::read(SRC + "/datasets/slam/paper_arena_obs.rawlog").sweeps;
	sweeps.resize(n);
	return sweeps;
}

std::vector<mrpt::poses::CPose2D> run(slam::TSlamParams p, const std::vector<obs::RawlogReader::Sweep>& sweeps)
{
	slam::RbpfSlam s(p, maps::MapConfig::load(p.map_config));
	for (const auto& sw : sweeps) s.step(sw);
	return s.bestPath();
}

class TSlamParamsTest : public test::TempDirTest
{
   protected:
	std::string ini(const std::string& text)
	{
		std::ofstream(path("s.ini")) << text;
		return path("s.ini");
	}
};
}  // namespace

TEST(TSlamParams, ShippedConfigLoads)
{
	const auto p = slam::TSlamParams::load(SLAM_INI);
	EXPECT_EQ(p.particles, 30u);
	EXPECT_EQ(p.seed, 1u);
	EXPECT_EQ(p.map_config, SRC + "/config/whisker-map.ini");  // beside the .ini
	EXPECT_TRUE(p.motion.matched_model);
	EXPECT_DOUBLE_EQ(p.motion.translation_noise, 0.05);  // the default odometry preset
	EXPECT_EQ(p.resampling, mrpt::bayes::CParticleFilter::prSystematic);
	EXPECT_EQ(p.proposal_samples, 10u);
	EXPECT_TRUE(p.manhattan_walls);  // walls along the start frame's axes, lengthened 0.3 m in the likelihood
	EXPECT_EQ(p.wall_axis, 0);
	EXPECT_EQ(p.wall_extension, 0.3);
}

// config/whisker-slam-100.ini is the shipped config with 100 particles in batches of 4: every
// other [slam] setting the same (a change to one file must reach the other; [smooth]:
// TSmoothParams_unittest).
TEST(TSlamParams, HundredParticleConfigDiffersOnlyInCountAndBatch)
{
	const std::string hundred = SRC + "/config/whisker-slam-100.ini";
	const auto a = slam::TSlamParams::load(SLAM_INI), b = slam::TSlamParams::load(hundred);
	EXPECT_EQ(a.batch_sweeps, 2u);
	EXPECT_EQ(b.particles, 100u);
	EXPECT_EQ(b.batch_sweeps, 4u);
	EXPECT_EQ(a.seed, b.seed);
	EXPECT_EQ(a.map_config, b.map_config);
	EXPECT_EQ(a.motion.translation_noise, b.motion.translation_noise);
	EXPECT_EQ(a.motion.rotation_noise, b.motion.rotation_noise);
	EXPECT_EQ(a.motion.turn_noise, b.motion.turn_noise);
	EXPECT_EQ(a.motion.scale_bias, b.motion.scale_bias);
	EXPECT_EQ(a.motion_noise_scale, b.motion_noise_scale);
	EXPECT_EQ(a.proposal_samples, b.proposal_samples);
	EXPECT_EQ(a.manhattan_walls, b.manhattan_walls);
	EXPECT_EQ(a.wall_axis, b.wall_axis);
	EXPECT_EQ(a.wall_extension, b.wall_extension);
	EXPECT_EQ(a.leg_merge_gap, b.leg_merge_gap);
	EXPECT_TRUE(a.disjoint_tables);
	EXPECT_EQ(a.disjoint_tables, b.disjoint_tables);
	EXPECT_EQ(a.resample_ess, b.resample_ess);
	EXPECT_EQ(a.resampling, b.resampling);
}

TEST_F(TSlamParamsTest, StrictKeysAndValues)
{
	EXPECT_NO_THROW(slam::TSlamParams::load(ini("[slam]\nodometry_model = poor\nresampling = residual\n")));
	const auto p = slam::TSlamParams::load(ini("[slam]\nodometry_model = poor\n"));
	EXPECT_DOUBLE_EQ(p.motion.translation_noise, 0.10);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nparticle = 3\n")), core::Error);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nresample_ess = 1.5\n")), core::Error);
	EXPECT_EQ(slam::TSlamParams::load(ini("[slam]\nproposal_samples = 12\n")).proposal_samples, 12u);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nproposal_samples = 0\n")), core::Error);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\n[other]\n")), core::Error);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nodometry_model = bumpy\n")), core::Error);
	const auto manhattan = slam::TSlamParams::load(ini("[slam]\nmanhattan_walls = true\nwall_axis_deg = -30\n"));
	EXPECT_TRUE(manhattan.manhattan_walls);
	EXPECT_NEAR(manhattan.wall_axis, -M_PI / 6, 1e-15);
	EXPECT_FALSE(slam::TSlamParams::load(ini("[slam]\n")).manhattan_walls);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nwall_axis_deg = 120\n")), core::Error);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nmanhattan_walls = maybe\n")), core::Error);
	EXPECT_EQ(slam::TSlamParams::load(ini("[slam]\nwall_extension = 0.5\n")).wall_extension, 0.5);
	EXPECT_EQ(slam::TSlamParams::load(ini("[slam]\n")).wall_extension, 0);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nwall_extension = -0.1\n")), core::Error);
	EXPECT_EQ(slam::TSlamParams::load(ini("[slam]\nleg_merge_gap = 0.02\n")).leg_merge_gap, 0.02);
	EXPECT_EQ(slam::TSlamParams::load(ini("[slam]\n")).leg_merge_gap, 0);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nleg_merge_gap = 2\n")), core::Error);
	EXPECT_TRUE(slam::TSlamParams::load(ini("[slam]\ndisjoint_tables = true\n")).disjoint_tables);
	EXPECT_FALSE(slam::TSlamParams::load(ini("[slam]\n")).disjoint_tables);
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\ndisjoint_tables = 2\n")), core::Error);
	EXPECT_THROW(slam::TSlamParams::load(path("missing.ini")), core::Error);
	// Exact odometry needs no [motion_model] (its matched model has zero noise); a noisy file
	// without one is refused.
	EXPECT_TRUE(slam::TSlamParams::load(ini("[slam]\nodometry_model = exact\n")).motion.matched_model);
	std::ofstream(path("noisy.ini")) << "[odometry]\ntranslation_noise=0.05\nrotation_noise_deg=0\nturn_noise=0\n"
										"turn_translation_noise=0\nscale_bias=0\n";
	EXPECT_THROW(slam::TSlamParams::load(ini("[slam]\nodometry_model = noisy.ini\n")), core::Error);
	// Exact odometry runs one particle (the others would repeat it); exact odometry with a
	// [motion_model] floor still spreads the particles, and so does any noisy preset.
	const auto exact = slam::TSlamParams::load(ini("[slam]\nodometry_model = exact\nparticles = 40\n"));
	EXPECT_TRUE(exact.exactMotion());
	EXPECT_EQ(exact.particles, 40u);
	EXPECT_EQ(exact.filterParticles(), 1u);
	std::ofstream(path("floored.ini")) << "[odometry]\ntranslation_noise=0\nrotation_noise_deg=0\nturn_noise=0\n"
										  "turn_translation_noise=0\nscale_bias=0\n[motion_model]\nmin_std_xy=0.001\n"
										  "min_std_phi_deg=0\n";
	const auto floored = slam::TSlamParams::load(ini("[slam]\nodometry_model = floored.ini\nparticles = 40\n"));
	EXPECT_FALSE(floored.exactMotion());
	EXPECT_EQ(floored.filterParticles(), 40u);
	EXPECT_EQ(slam::TSlamParams::load(ini("[slam]\nparticles = 40\n")).filterParticles(), 40u);
}

TEST(RbpfSlam, OnePosePerSweepFromTheKnownStart)
{
	auto p = slam::TSlamParams::load(SLAM_INI);
	p.particles = 4;
	const auto sweeps = firstSweeps(40);
	slam::RbpfSlam s(p, maps::MapConfig::load(p.map_config));
	for (const auto& sw : sweeps)
	{
		const auto& st = s.step(sw);
		EXPECT_TRUE(st.ess > 0 && st.ess <= 1 + 1e-9);
	}
	const auto path = s.bestPath();
	ASSERT_EQ(path.size(), sweeps.size());
	ASSERT_EQ(s.stepCount(), sweeps.size());
	// The first pose is the start plus one step's motion noise (millimetres).
	EXPECT_LT(path[0].distanceTo(sweeps[0].robotPose), 0.01);
	EXPECT_EQ(s.particles().particlesCount(), 4u);
}

TEST(RbpfSlam, SettledPosesAndTheBestPathMakeOnePathInBoundedMemory)
{
	// Never resampled (resample_ess 0), three particles' lineages never meet: with a limit of
	// 60 poses, settle() cuts them at a lag of 60 / (4 x 3) = 5 sweeps whenever more are
	// kept, so the poses kept stay at the limit, and the poses handed over plus the best path are one pose per sweep.
	auto p = slam::TSlamParams::load(SLAM_INI);
	p.particles = 3, p.resample_ess = 0;
	const auto sweeps = firstSweeps(120);
	slam::RbpfSlam s(p, maps::MapConfig::load(p.map_config));
	s.setPathLimit(60);
	std::vector<mrpt::poses::CPose2D> path;
	size_t most = 0;
	for (const auto& sw : sweeps)
	{
		s.step(sw);
		const size_t handed = s.settle([&](const mrpt::poses::CPose2D& q) { path.push_back(q); });
		EXPECT_EQ(s.settledSweeps(), path.size());
		EXPECT_LE(handed, path.size());
		most = std::max(most, s.paths().nodes());
	}
	EXPECT_LE(most, 60u + 3u);  // one step's growth past the limit before the cut
	EXPECT_GT(path.size(), 100u);
	const auto rest = s.bestPath();
	EXPECT_LE(rest.size(), 60u / 3);  // what the limit leaves a particle
	path.insert(path.end(), rest.begin(), rest.end());
	ASSERT_EQ(path.size(), sweeps.size());
	EXPECT_LT(path[0].distanceTo(sweeps[0].robotPose), 0.01);
	EXPECT_LT(path.back().distanceTo(sweeps.back().robotPose), 0.5);
}

TEST(RbpfSlam, SameSeedSamePathOtherSeedOtherPath)
{
	auto p = slam::TSlamParams::load(SLAM_INI);
	p.particles = 3;
	const auto sweeps = firstSweeps(30);
	const auto a = run(p, sweeps), b = run(p, sweeps);
	p.seed = 2;
	const auto c = run(p, sweeps);
	bool same = true, other = false;
	for (size_t i = 0; i < a.size(); i++)
	{
		same &= a[i] == b[i];
		other |= !(a[i] == c[i]);
	}
	EXPECT_TRUE(same);
	EXPECT_TRUE(other);
}

TEST_F(TSlamParamsTest, ExactOdometryModelFollowsTheOdometry)
{
	// With `odometry_model = exact` on an exact-odometry log (the paper arena's), every
	// particle stays on the recorded path, the truth: SLAM maps at the true poses.
	auto p = slam::TSlamParams::load(ini("[slam]\nodometry_model = exact\nparticles = 3\nmap_config = " + SRC +
										 "/config/whisker-map.ini\n"));
	auto sweeps = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog").sweeps;
	sweeps.resize(60);
	EXPECT_EQ(slam::RbpfSlam(p, maps::MapConfig::load(p.map_config)).particles().particlesCount(), 1u);
	const auto path = run(p, sweeps);
	ASSERT_EQ(path.size(), sweeps.size());
	for (size_t i = 0; i < path.size(); i++)
	{
		EXPECT_LT(path[i].distanceTo(sweeps[i].robotPose), 1e-9) << "sweep " << i;
		EXPECT_NEAR(mrpt::math::wrapToPi(path[i].phi() - sweeps[i].robotPose.phi()), 0, 1e-9) << "sweep " << i;
	}
}

TEST_F(TSlamParamsTest, HeadingExactOdometryModelKeepsTheHeadingsTurns)
{
	// An odometry exact in heading only (a gyro's, say: every rotation term and floor zero):
	// the particles take the recorded turns exactly and still spread in position.
	std::ofstream(path("gyro.ini")) << "[odometry]\ntranslation_noise = 0.05\nrotation_noise_deg = 0\nturn_noise = 0\n"
									   "turn_translation_noise = 0\nscale_bias = 0.01\n"
									   "[motion_model]\nmin_std_xy = 0.001\nmin_std_phi_deg = 0\n";
	auto p = slam::TSlamParams::load(ini("[slam]\nodometry_model = " + path("gyro.ini") + "\nparticles = 3\nmap_config = " +
										 SRC + "/config/whisker-map.ini\n"));
	const auto sweeps = firstSweeps(80);
	EXPECT_EQ(slam::RbpfSlam(p, maps::MapConfig::load(p.map_config)).particles().particlesCount(), 3u);
	const auto path = run(p, sweeps);
	ASSERT_EQ(path.size(), sweeps.size());
	double apart = 0;
	for (size_t i = 1; i < path.size(); i++)
	{
		const double turn = path[i].phi() - path[i - 1].phi(), recorded = sweeps[i].robotPose.phi() - sweeps[i - 1].robotPose.phi();
		EXPECT_NEAR(mrpt::math::wrapToPi(turn - recorded), 0, 1e-9) << "sweep " << i;
		apart = std::max(apart, path[i].distanceTo(sweeps[i].robotPose));
	}
	EXPECT_GT(apart, 0.005);  // positions are the filter's own, not the odometry's
}

TEST(RbpfSlam, BestMapIsTheMapBuiltAtItsPath)
{
	// The particle's map is what the map makes of the sweeps at the particle's poses: the
	// property whisker-slam relies on to write the map with whisker-map's writer.
	auto p = slam::TSlamParams::load(SLAM_INI);
	p.particles = 3;
	const auto sweeps = firstSweeps(200);
	const auto inits = maps::MapConfig::load(p.map_config);
	slam::RbpfSlam s(p, inits);
	for (const auto& sw : sweeps) s.step(sw);
	const auto path = s.bestPath();
	mrpt::maps::CMultiMetricMap mm(inits);
	for (size_t i = 0; i < sweeps.size(); i++) mm.insertObservation(*sweeps[i].obs, mrpt::poses::CPose3D(path[i]));
	auto rebuilt = mm.mapByClass<maps::CHierarchicalObjectMap>()->mapTables();
	auto best = s.bestMap().mapTables();
	ASSERT_FALSE(best.empty());  // 200 sweeps touch tables
	// As sets: a particle's map, copied at resamplings, numbers its tables its own way.
	const auto byPosition = [](const world::Table& a, const world::Table& b) { return std::tie(a.x, a.y) < std::tie(b.x, b.y); };
	std::sort(rebuilt.begin(), rebuilt.end(), byPosition);
	std::sort(best.begin(), best.end(), byPosition);
	ASSERT_EQ(rebuilt.size(), best.size());
	for (size_t i = 0; i < best.size(); i++)
	{
		EXPECT_EQ(rebuilt[i].x, best[i].x);
		EXPECT_EQ(rebuilt[i].y, best[i].y);
	}
}

TEST(RbpfSlam, ResamplingLeavesEqualWeightsAndOneLatestPosePerParticle)
{
	auto p = slam::TSlamParams::load(SLAM_INI);
	p.particles = 6;
	const auto sweeps = firstSweeps(400);
	slam::RbpfSlam s(p, maps::MapConfig::load(p.map_config));
	// Up to a sweep after which particles of clearly different weights are all likely to
	// survive (and no resampling is pending), so that the copies' parents differ in weight.
	const auto& pdf = s.particles();
	const auto spread = [&] {
		double lo = 0;  // the largest log weight is 0 (normalised)
		for (size_t i = 0; i < pdf.particlesCount(); i++) lo = std::min(lo, pdf.getW(i));
		return lo;
	};
	size_t k = 0;
	for (; k < sweeps.size(); k++)
	{
		if (!s.step(sweeps[k]).resampled && spread() < -0.2 && spread() > -1) break;
	}
	ASSERT_LT(k, sweeps.size());
	std::vector<std::vector<mrpt::math::TPose2D>> before;
	for (size_t i = 0; i < s.paths().particles(); i++) before.push_back(s.paths().path(i));
	s.resample();
	for (size_t i = 0; i < pdf.particlesCount(); i++)
	{
		EXPECT_EQ(pdf.getW(i), 0.0) << i;  // MRPT 2.5.8's performResampling keeps the parents' weights
		EXPECT_EQ(pdf.m_particles[i].d->robotPath.size(), 1u);  // the paths live in the PathTree
	}
	// Every path is a survivor's path from before, and the latest poses are the particles'.
	const auto same = [](const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) {
		return a.x == b.x && a.y == b.y && a.phi == b.phi;
	};
	for (size_t i = 0; i < s.paths().particles(); i++)
	{
		const auto path = s.paths().path(i);
		ASSERT_EQ(path.size(), k + 2);
		EXPECT_TRUE(std::any_of(before.begin(), before.end(), [&](const auto& b) {
			return std::equal(b.begin(), b.end(), path.begin(), same);
		}));
		const auto& q = pdf.m_particles[i].d->robotPath.back();
		EXPECT_TRUE(same(path.back(), {q.x, q.y, q.yaw}));
	}
}

TEST(RbpfSlam, ResampledCopiesAreClonesThatGoTheirOwnWay)
{
	// Copies of one parent are clones (copy constructors): equal maps whose swept grids share
	// every chunk, not MRPT's serialized copies (which share nothing). Then each goes its own
	// way: a sweep inserted into one leaves the other as it was.
	auto p = slam::TSlamParams::load(SLAM_INI);
	p.particles = 6;
	const auto sweeps = firstSweeps(400);
	slam::RbpfSlam s(p, maps::MapConfig::load(p.map_config));
	size_t k = 0;
	while (k < sweeps.size() && !(s.stepCount() > 0 && s.lastStep().resampled)) s.step(sweeps[k++]);
	ASSERT_LT(k, sweeps.size());  // the ESS fell below resample_ess: some parent will be drawn twice
	s.resample();
	const auto& pdf = s.particles();
	const auto mapOf = [&](size_t i) { return pdf.m_particles[i].d->mapTillNow.mapByClass<maps::CHierarchicalObjectMap>(); };
	const auto samePose = [&](size_t i, size_t j) {
		const auto &a = pdf.m_particles[i].d->robotPath.back(), &b = pdf.m_particles[j].d->robotPath.back();
		return a.x == b.x && a.y == b.y && a.yaw == b.yaw;
	};
	std::vector<size_t> twins;  // i: particle i is a copy of particle i - 1's parent too
	for (size_t i = 1; i < pdf.particlesCount(); i++)
	{
		if (!samePose(i, i - 1)) continue;
		twins.push_back(i);
		const auto a = mapOf(i - 1), b = mapOf(i);
		ASSERT_TRUE(a && b);
		EXPECT_NE(a.get(), b.get());
		EXPECT_GT(b->sweptGrid().chunkCount(), 0u);
		EXPECT_EQ(b->sweptGrid().sharedChunks(), b->sweptGrid().chunkCount()) << i;
		const auto sharing = b->lastingMap().state().sharing();  // and the lasting state's arrays and grids
		EXPECT_GT(sharing.chunks, 0u);
		EXPECT_EQ(sharing.shared, sharing.chunks) << i;
		EXPECT_EQ(b->asString(), a->asString());
	}
	ASSERT_FALSE(twins.empty());
	const auto a = mapOf(twins[0] - 1), b = mapOf(twins[0]);
	const std::string before = a->asString();
	b->insertObservation(*sweeps[k].obs, mrpt::poses::CPose3D(sweeps[k].robotPose));
	EXPECT_EQ(a->asString(), before);
	EXPECT_NE(b->asString(), before);
	// The sweep wrote into some of the lasting state's chunks, not all (this early map is small
	// and near the sweep: 15 of 38 stay shared): the copy's memory is what its sweep changed.
	const auto sharing = b->lastingMap().state().sharing();
	EXPECT_LT(sharing.shared, sharing.chunks);
	EXPECT_GT(sharing.shared, 0u);
}
