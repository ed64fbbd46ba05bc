#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/Se2Alignment.h>

using namespace whiskermap;
using Vec = Eigen::Vector2d;

TEST(Se2Alignment, RecoversAKnownRotationAndTranslationExactly)
{
	const std::vector<Vec> from{{0, 0}, {1, 0}, {1, 2}, {-0.5, 3}, {2.5, -1}};
	eval::Se2Alignment truth;
	truth.yaw = core::deg2rad(30);
	truth.t = Vec(1.0, -2.0);
	std::vector<Vec> to;
	for (const auto& p : from) to.push_back(truth.apply(p));
	// By hand: (1, 0) turned 30 degrees is (cos 30, sin 30) = (0.866..., 0.5), then + (1, -2).
	EXPECT_NEAR(to[1].x(), 1 + std::sqrt(3.0) / 2, 1e-15);
	EXPECT_NEAR(to[1].y(), -1.5, 1e-15);
	const auto a = eval::Se2Alignment::fit(from, to);
	EXPECT_NEAR(core::rad2deg(a.yaw), 30, 1e-12);
	EXPECT_NEAR(a.t.x(), 1.0, 1e-12);
	EXPECT_NEAR(a.t.y(), -2.0, 1e-12);
	const auto pose = a.apply(mrpt::poses::CPose2D(1, 0, core::deg2rad(10)));
	EXPECT_NEAR(core::rad2deg(pose.phi()), 40, 1e-12);
}

TEST(Se2Alignment, DegenerateSets)
{
	// A copy scaled by sqrt(2) (the fit has no scale): by hand, dot = 2, cross = 2, yaw 45 deg.
	const auto a = eval::Se2Alignment::fit({{1, 0}, {-1, 0}}, {{1, 1}, {-1, -1}});
	EXPECT_NEAR(core::rad2deg(a.yaw), 45, 1e-12);
	EXPECT_NEAR(a.t.norm(), 0, 1e-15);
	// One point: a pure shift.
	const auto b = eval::Se2Alignment::fit({{1, 2}}, {{4, 6}});
	EXPECT_EQ(b.yaw, 0);
	EXPECT_EQ(b.t, Vec(3, 4));
	EXPECT_THROW(eval::Se2Alignment::fit({{1, 2}}, {}), core::Error);
}
