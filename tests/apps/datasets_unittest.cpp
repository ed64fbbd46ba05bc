// Tests on the shipped, recorded datasets (datasets/paper_arena/) and the paper arena.
#include <gtest/gtest.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>

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
