#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
world::World arena() { return world::World::load(SRC + "/config/worlds/paper_arena.ini"); }
world::Robot robot() { return world::Robot::load(SRC + "/config/robots/scratchbot.ini"); }
const auto T0 = mrpt::Clock::fromDouble(1e9);
}  // namespace

TEST(WhiskerSimulator, PoseInsideALegIsNotFree)
{
	const auto w = arena();
	world::WhiskerSimulator sim(w, robot(), {}, 1);
	const auto leg = w.tables[0].legCentre(0);
	EXPECT_FALSE(sim.poseIsFree({leg.x(), leg.y(), 0}));
	EXPECT_FALSE(sim.poseIsFree({w.x_min + 0.05, 2.0, 0}));  // body through the wall
	for (const auto& p : world::Trajectory::paperGrid(w)) EXPECT_TRUE(sim.poseIsFree(p));
}

TEST(WhiskerSimulator, NoiselessReadingsLieOnTheSurfaces)
{
	const auto w = arena();
	world::WhiskerSimulator sim(w, robot(), {}, 1);
	const auto obstacles = w.obstacles();
	std::vector<world::WhiskerSimulator::Truth> truth;
	size_t checked = 0;
	for (const auto& p : world::Trajectory::paperGrid(w))
	{
		const auto o = sim.sense(p, T0, &truth);
		const auto shapelets = o->toShapelets(p);
		for (const auto& s : shapelets)
		{
			const auto& t = truth[s.whisker];
			double best = INFINITY;
			for (const auto& ob : obstacles)
				if (ob.table == t.table && ob.leg == t.leg) best = std::min(best, ob.distance({s.x, s.y}));
			EXPECT_LT(best, 1e-9);  // the contact point is on the touched solid
			if (t.table >= 0) { EXPECT_DOUBLE_EQ(s.texture, w.tables[t.table].texture); }
			checked++;
		}
	}
	EXPECT_GT(checked, 1000u);
}

TEST(WhiskerSimulator, NoiseHasTheConfiguredStatistics)
{
	const auto w = arena();
	const obs::TSensorNoise noise{0.02, core::deg2rad(5), 0.05};
	world::WhiskerSimulator exact(w, robot(), {}, 1), noisy(w, robot(), noise, 99);
	double sr = 0, sr2 = 0, sp = 0, sp2 = 0, st = 0, st2 = 0;
	size_t n = 0;
	const auto poses = world::Trajectory::paperGrid(w);
	for (int rep = 0; rep < 10; rep++)
		for (const auto& p : poses)
		{
			const auto a = exact.sense(p, T0), b = noisy.sense(p, T0);
			for (size_t i = 0; i < a->whiskers.size(); i++)
			{
				const auto &x = a->whiskers[i], &y = b->whiskers[i];
				ASSERT_EQ(x.touched, y.touched);  // noise never changes what is touched
				// Skip readings that the clamps to [0, length] or [0, 1] could bias.
				if (!x.touched || x.r < 0.1 || x.r > x.length - 0.1 || x.texture < 0.25 ||
					x.texture > 0.75)
					continue;
				const double dr = y.r - x.r, dp = core::wrapToPi(y.normal - x.normal),
							 dt = y.texture - x.texture;
				sr += dr, sr2 += dr * dr, sp += dp, sp2 += dp * dp, st += dt, st2 += dt * dt;
				n++;
			}
		}
	ASSERT_GT(n, 3000u);
	auto check = [&](double s, double s2, double sigma) {
		const double mean = s / n, sd = std::sqrt(s2 / n - mean * mean);
		EXPECT_LT(std::abs(mean), 4 * sigma / std::sqrt(double(n)));
		EXPECT_NEAR(sd, sigma, 0.05 * sigma);
	};
	check(sr, sr2, noise.sigma_r);
	check(sp, sp2, noise.sigma_phi);
	check(st, st2, noise.sigma_tau);
}

TEST(WhiskerSimulator, SameSeedSameSweepsOtherSeedOtherSweeps)
{
	const obs::TSensorNoise noise{0.01, 0.1, 0.05};
	world::WhiskerSimulator a(arena(), robot(), noise, 42), b(arena(), robot(), noise, 42),
		c(arena(), robot(), noise, 43);
	bool anyDiff = false;
	for (const auto& p : world::Trajectory::paperGrid(arena(), 4))
	{
		const auto x = a.sense(p, T0), y = b.sense(p, T0), z = c.sense(p, T0);
		for (size_t i = 0; i < x->whiskers.size(); i++)
		{
			EXPECT_EQ(x->whiskers[i].r, y->whiskers[i].r);
			EXPECT_EQ(x->whiskers[i].normal, y->whiskers[i].normal);
			anyDiff = anyDiff || x->whiskers[i].r != z->whiskers[i].r;
		}
	}
	EXPECT_TRUE(anyDiff);
}
