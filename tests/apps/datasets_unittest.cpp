// Tests on the shipped, recorded datasets (datasets/paper_arena/, datasets/office/,
// datasets/slam/) and the
// paper arena.
#include <gtest/gtest.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CRawlog.h>
#include <whiskermap/eval/TrajectoryEvaluation.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/OdometryNoise.h>
#include <whiskermap/world/PathLog.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/TrajectoryGenerator.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>
#include <set>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
}

TEST(PaperArenaDatasets, EachLoadsWithTheExpectedEntries)
{
	const auto grid = world::Trajectory::paperGrid(
		world::World::load(SRC + "/config/worlds/paper_arena.ini"));
	for (const char* preset : {"noiseless", "default", "very-noisy"})
	{
		const auto c =
			obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog");
		EXPECT_EQ(c.objects, 800u) << preset;  // odometry + sweep per pose
		ASSERT_EQ(c.sweeps.size(), 400u) << preset;
		EXPECT_FALSE(c.actionSensoryFrameFormat);
		for (size_t i = 0; i < grid.size(); i++)
			EXPECT_NEAR((c.sweeps[i].robotPose - grid[i]).norm(), 0, 1e-12);
		EXPECT_EQ(c.sweeps[0].obs->whiskers.size(), 6u);
	}
}

TEST(PaperArenaDatasets, NoiseLevelsAreTheNamedPresets)
{
	auto sigmaR = [](const char* preset) {
		return obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog")
			.sweeps[0]
			.obs->noise.sigma_r;
	};
	EXPECT_EQ(sigmaR("noiseless"), 0.0);
	EXPECT_EQ(sigmaR("default"), 0.01);
	EXPECT_EQ(sigmaR("very-noisy"), 0.05);  // the paper's 0.5 units at 0.1 m per unit
}

TEST(OfficeDatasets, EachLoadsAndTouchesTheInteriorWallsAndEveryObject)
{
	// datasets/office/: office.ini's 12 x 12 grid (4 headings), blocked poses skipped.
	const auto w = world::World::load(SRC + "/config/worlds/office.ini");
	ASSERT_EQ(w.walls.size(), 2u);
	ASSERT_GE(w.tables.size(), 10u);
	world::WhiskerSimulator sim(w, world::Robot::load(SRC + "/config/robots/scratchbot.ini"), {}, 1);
	std::vector<mrpt::poses::CPose2D> free;
	for (const auto& p : world::Trajectory::paperGrid(w, 12))
		if (sim.poseIsFree(p)) free.push_back(p);
	for (const char* preset : {"noiseless", "default", "very-noisy"})
	{
		const auto c = obs::RawlogReader::read(SRC + "/datasets/office/" + preset + ".rawlog");
		ASSERT_EQ(c.sweeps.size(), free.size()) << preset;
		for (size_t i = 0; i < free.size(); i++) EXPECT_NEAR((c.sweeps[i].robotPose - free[i]).norm(), 0, 1e-12);
	}
	// The path covers the office: every object touched on >= 2 legs, both partitions touched
	// (a contact on an interior wall's face: on its slab, not on the arena's walls).
	const auto truthWorld = world::World::load(SRC + "/datasets/office/default_ground_truth_world.ini");
	EXPECT_EQ(truthWorld.walls.size(), 2u);
	std::vector<std::set<int>> legs(w.tables.size());
	std::vector<size_t> onWall(w.walls.size(), 0);
	std::vector<world::WhiskerSimulator::Truth> truth;
	for (const auto& p : free)
	{
		const auto o = sim.sense(p, mrpt::Clock::fromDouble(1e9), &truth);
		for (const auto& s : o->toShapelets(p))
		{
			if (truth[s.whisker].table >= 0) legs[truth[s.whisker].table].insert(truth[s.whisker].leg);
			for (size_t k = 0; k < w.walls.size(); k++) onWall[k] += w.walls[k].slab().distance({s.x, s.y}) < 1e-9;
		}
	}
	for (size_t i = 0; i < legs.size(); i++) EXPECT_GE(legs[i].size(), 2u) << "object " << i;
	for (size_t k = 0; k < onWall.size(); k++) EXPECT_GT(onWall[k], 20u) << "wall " << k;
}

TEST(PaperArena, ReproducesThePapersContactStatistic)
{
	// Over poses touching at least one table, whiskers touching tables: paper 4.2 +/- 1.7.
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	world::WhiskerSimulator sim(
		w, world::Robot::load(SRC + "/config/robots/scratchbot.ini"), {}, 1);
	std::vector<world::WhiskerSimulator::Truth> truth;
	double sum = 0, sumSq = 0;
	int n = 0;
	for (const auto& p : world::Trajectory::paperGrid(w))
	{
		sim.sense(p, mrpt::Clock::fromDouble(1e9), &truth);
		int k = 0;
		for (const auto& t : truth) k += t.table >= 0;
		if (k == 0) continue;
		sum += k, sumSq += k * k, n++;
	}
	const double mean = sum / n, sd = std::sqrt((sumSq - n * mean * mean) / (n - 1));
	EXPECT_NEAR(mean, 4.2, 0.5);
	EXPECT_NEAR(sd, 1.7, 0.5);
	EXPECT_GT(n, 200);  // most poses touch a table
}

// ---- datasets/slam/: continuous lawnmower paths with noisy odometry (doc/slam.md) ----

namespace
{
struct SlamDataset
{
	std::string name, world;  // dataset stem (without layout), world file it was made from
};
const SlamDataset SLAM_DATASETS[] = {
	{"paper_arena", "/config/worlds/paper_arena.ini"},
	{"random_yaw1", "/config/worlds/eval/random_yaw/seed1.ini"},
};
const char* LAYOUTS[] = {"obs", "action-sf"};
std::string slamFile(const SlamDataset& d, const std::string& layout, const std::string& suffix)
{
	return SRC + "/datasets/slam/" + d.name + "_" + layout + suffix;
}
/** The spec and seed scripts/make-datasets.sh uses. */
std::vector<mrpt::poses::CPose2D> slamTruth(const SlamDataset& d)
{
	world::TrajectorySpec s;
	s.speed = 0.4, s.rate = 8;
	return world::TrajectoryGenerator::generate(
		world::World::load(SRC + d.world), world::Robot::load(SRC + "/config/robots/scratchbot.ini"), s, 2011);
}
}  // namespace

TEST(SlamDatasets, TheTruthIsTheGeneratedLawnmowerAtEightHertz)
{
	for (const auto& d : SLAM_DATASETS)
	{
		const auto truth = slamTruth(d);
		const auto w = world::World::load(slamFile(d, "obs", "_ground_truth_world.ini"));
		EXPECT_EQ(w.tables.size(), world::World::load(SRC + d.world).tables.size());
		const world::WhiskerSimulator sim(w, world::Robot::load(SRC + "/config/robots/scratchbot.ini"), {}, 1);
		for (const char* layout : LAYOUTS)
		{
			const auto gt = world::PathLog::read(slamFile(d, layout, "_ground_truth_robot_path.txt"));
			ASSERT_EQ(gt.size(), truth.size()) << d.name;
			EXPECT_GT(gt.size(), 800u);
			EXPECT_LT(gt.size(), 3000u);  // a few thousand sweeps at most
			for (size_t i = 0; i < gt.size(); i++)
			{
				EXPECT_NEAR(gt[i].t, 1300000000.0 + i / 8.0, 1e-6);
				EXPECT_NEAR((mrpt::poses::CPose2D(gt[i].pose) - truth[i]).norm(), 0, 2e-9);
				EXPECT_TRUE(sim.poseIsFree(truth[i]));
				if (i > 0) { EXPECT_LE((truth[i] - truth[i - 1]).norm(), 0.05 + 1e-9); }  // continuous: 5 cm steps
			}
		}
	}
}

TEST(SlamDatasets, TheOdometryIsRecordedNoisyAndTheSameInBothLayouts)
{
	for (const auto& d : SLAM_DATASETS)
	{
		const auto obsLog = obs::RawlogReader::read(slamFile(d, "obs", ".rawlog"));
		const auto sfLog = obs::RawlogReader::read(slamFile(d, "action-sf", ".rawlog"));
		const auto odo = world::PathLog::read(slamFile(d, "obs", "_odometry_path.txt"));
		const auto gt = world::PathLog::read(slamFile(d, "obs", "_ground_truth_robot_path.txt"));
		ASSERT_EQ(obsLog.sweeps.size(), gt.size()) << d.name;
		ASSERT_EQ(sfLog.sweeps.size(), gt.size()) << d.name;
		EXPECT_FALSE(obsLog.actionSensoryFrameFormat);
		EXPECT_TRUE(sfLog.actionSensoryFrameFormat);
		EXPECT_EQ(obsLog.objects, 2 * gt.size());
		for (size_t i = 0; i < gt.size(); i++)
		{
			EXPECT_NEAR((obsLog.sweeps[i].robotPose - mrpt::poses::CPose2D(odo[i].pose)).norm(), 0, 2e-9);
			EXPECT_NEAR((sfLog.sweeps[i].robotPose - mrpt::poses::CPose2D(odo[i].pose)).norm(), 0, 1e-8);  // composed increments
			EXPECT_EQ(obsLog.sweeps[i].obs->timestamp, sfLog.sweeps[i].obs->timestamp);
			ASSERT_EQ(obsLog.sweeps[i].obs->whiskers.size(), sfLog.sweeps[i].obs->whiskers.size());
			for (size_t k = 0; k < obsLog.sweeps[i].obs->whiskers.size(); k++)
				EXPECT_EQ(obsLog.sweeps[i].obs->whiskers[k].r, sfLog.sweeps[i].obs->whiskers[k].r);
		}
		EXPECT_EQ(odo.front().pose, gt.front().pose);  // known start
		const auto ate = eval::TrajectoryEvaluation::compute(odo, gt, eval::EvalOptions{});
		EXPECT_GT(ate.ate_rmse_m, 0.05) << d.name;  // default noise: tens of centimetres
		EXPECT_LT(ate.ate_rmse_m, 1.5) << d.name;
		EXPECT_NEAR(ate.rpe_rot_deg_per_m, 2, 1.5) << d.name;
		EXPECT_EQ(obsLog.sweeps[0].obs->noise.sigma_r, 0.01);  // default sensor noise
	}
}

TEST(SlamDatasets, TheSweepsAreWhatTheSimulatorSensesAtTheTruePoses)
{
	// The sensor noise stream is independent of the odometry noise: simulating the same path
	// with the same seed (and no odometry at all) gives these sweeps bit for bit.
	for (const auto& d : SLAM_DATASETS)
	{
		const auto log = obs::RawlogReader::read(slamFile(d, "obs", ".rawlog"));
		world::WhiskerSimulator sim(
			world::World::load(SRC + d.world), world::Robot::load(SRC + "/config/robots/scratchbot.ini"),
			world::NoisePreset::load("default"), 2011);
		const auto truth = slamTruth(d);
		ASSERT_EQ(truth.size(), log.sweeps.size());
		for (size_t i = 0; i < truth.size(); i++)
		{
			const auto s = sim.sense(truth[i], log.sweeps[i].obs->timestamp);
			for (size_t k = 0; k < s->whiskers.size(); k++)
			{
				EXPECT_EQ(s->whiskers[k].touched, log.sweeps[i].obs->whiskers[k].touched);
				EXPECT_EQ(s->whiskers[k].r, log.sweeps[i].obs->whiskers[k].r);
				EXPECT_EQ(s->whiskers[k].normal, log.sweeps[i].obs->whiskers[k].normal);
			}
		}
	}
}

TEST(SlamDatasets, EachActionCarriesTheMatchedMotionModel)
{
	const auto noise = world::OdometryNoise::load("default");
	for (const auto& d : SLAM_DATASETS)
	{
		mrpt::obs::CRawlog rawlog;
		ASSERT_TRUE(rawlog.loadFromRawLogFile(slamFile(d, "action-sf", ".rawlog")));
		size_t actions = 0;
		for (size_t i = 0; i < rawlog.size(); i++)
		{
			if (rawlog.getType(i) != mrpt::obs::CRawlog::etActionCollection) continue;
			const auto mv = rawlog.getAsAction(i)->getBestMovementEstimation();
			ASSERT_TRUE(mv);
			const auto expected = noise.motionModel(mv->rawOdometryIncrementReading).gaussianModel;
			const auto& got = mv->motionModelConfiguration.gaussianModel;
			EXPECT_EQ(mv->motionModelConfiguration.modelSelection, mrpt::obs::CActionRobotMovement2D::mmGaussian);
			EXPECT_FLOAT_EQ(got.a1, expected.a1);  // MRPT stores the model's coefficients as floats
			EXPECT_FLOAT_EQ(got.a3, expected.a3);
			EXPECT_FLOAT_EQ(got.a4, expected.a4);
			EXPECT_FLOAT_EQ(got.minStdXY, noise.min_std_xy);
			// A 5 cm step: 0.05 sqrt(0.05) + 1% of 5 cm + 1 mm = 1.27 cm of spread.
			if (std::abs(mv->rawOdometryIncrementReading.norm() - 0.05) < 0.002 && actions > 0)
			{
				EXPECT_NEAR(std::sqrt(mv->poseChange->getCovariance()(0, 0)), 0.0127, 0.0006);
			}
			actions++;
		}
		EXPECT_EQ(actions, obs::RawlogReader::read(slamFile(d, "action-sf", ".rawlog")).sweeps.size());
	}
}
