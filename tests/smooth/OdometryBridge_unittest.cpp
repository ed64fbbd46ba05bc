#include <gtest/gtest.h>
#include <whiskermap/smooth/OdometryBridge.h>

using namespace whiskermap;
using smooth::OdometryBridge;

namespace
{
/** 200 sweeps along +x, 5 cm a step, 1 cm and 0.57 degree std-dev a step: the odometry and
 *  its chain from the origin. */
struct Straight
{
	std::vector<smooth::OdometryFactor> odometry;
	OdometryBridge::Path chain;

	Straight()
	{
		const Eigen::Matrix3d cov = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
		for (size_t i = 0; i < 200; i++)
		{
			odometry.emplace_back(Eigen::Vector3d(i ? 0.05 : 0, 0, 0), cov);
			chain.push_back(i ? odometry[i].end(chain[i - 1]) : Eigen::Vector3d::Zero());
		}
	}
};
}  // namespace

TEST(OdometryBridge, StraysAreWhereThePathLeavesItsOdometry)
{
	Straight s;
	const auto onChain = OdometryBridge::distances(s.chain, s.odometry, 40);
	EXPECT_TRUE(OdometryBridge::strays(onChain, 40, 5).empty());
	EXPECT_LT(OdometryBridge::worst(onChain), 1e-9);
	// A path that takes 1 m sideways over sweeps 30-35 and comes back over 160-165 (a filter
	// locked onto a leg a table's width away): each move strays, and between them the path
	// follows the odometry, shifted.
	auto bent = s.chain;
	for (size_t i = 30; i < 200; i++)
		bent[i].y() += 0.2 * static_cast<double>(std::min<size_t>(i - 30, 5) - std::min<size_t>(i > 160 ? i - 160 : 0, 5));
	const auto onBent = OdometryBridge::distances(bent, s.odometry, 40);
	const auto strays = OdometryBridge::strays(onBent, 40, 5);
	ASSERT_EQ(strays.size(), 2u);
	EXPECT_GT(OdometryBridge::worst(onBent), 5);
	EXPECT_EQ(OdometryBridge::worst(OdometryBridge::distances(bent, s.odometry, 200)), 0);  // no window fits
	EXPECT_LE(strays[0].first, 30u);
	EXPECT_GE(strays[0].second, 35u);
	EXPECT_LT(strays[0].second, 160u);
	EXPECT_LE(strays[1].first, 160u);
	EXPECT_GE(strays[1].second, 165u);
	// A gentler curve, within the odometry's covariance, is no stray; a gate of 0 makes every
	// window one, all joined.
	auto gentle = s.chain;
	for (size_t i = 0; i < 200; i++) gentle[i].y() += 0.001 * static_cast<double>(i);
	const auto onGentle = OdometryBridge::distances(gentle, s.odometry, 40);
	EXPECT_TRUE(OdometryBridge::strays(onGentle, 40, 5).empty());
	EXPECT_EQ(OdometryBridge::strays(onGentle, 40, 0), (std::vector<OdometryBridge::Stretch>{{0, 199}}));
}

TEST(OdometryBridge, CandidatesAreEachStrayAndNeighboursTogetherWidened)
{
	const std::vector<OdometryBridge::Stretch> strays{{10, 60}, {100, 150}, {180, 195}};
	const std::vector<OdometryBridge::Stretch> expected{{0, 80}, {0, 170}, {80, 170}, {80, 199}, {160, 199}};
	EXPECT_EQ(OdometryBridge::candidates(strays, 20, 200), expected);
	EXPECT_TRUE(OdometryBridge::candidates({}, 20, 200).empty());
}

TEST(OdometryBridge, TheBridgeFollowsTheOdometryAndEndsOnThePath)
{
	Straight s;
	auto path = s.chain;
	for (size_t i = 50; i < 200; i++) path[i] += Eigen::Vector3d(0.02, 0.5, 0.1);  // a jump at sweep 50
	const auto b = OdometryBridge::bridge(path, s.odometry, {40, 60});
	ASSERT_EQ(b.size(), path.size());
	for (size_t i = 0; i < 200; i++)
	{
		if (i <= 40 || i >= 60)
		{
			EXPECT_LT((b[i] - path[i]).norm(), 1e-12) << i;
		}
	}
	// Inside, the odometry's 5 cm steps (the chain from sweep 40 heads along +x) with the jump
	// spread evenly over the 20 steps.
	for (size_t i = 41; i <= 60; i++) EXPECT_LT((b[i] - b[i - 1] - Eigen::Vector3d(0.051, 0.025, 0.005)).norm(), 1e-12) << i;
}

TEST(OdometryBridge, AShortBendHidesInALongWindow)
{
	// A path that steps 16 cm sideways over sweeps 100-103, follows the odometry there for
	// eight sweeps and steps back over 112-115 (a path bent onto a leg mapped beside its place,
	// both times it is touched): a window of 40 sweeps that sees the bend whole sees no net
	// motion, one that sees half of it holds it within its heading's covariance; a window of
	// 12 sees each step.
	Straight s;
	auto bent = s.chain;
	for (size_t i = 100; i < 200; i++)
		bent[i].y() += 0.04 * static_cast<double>(std::min<size_t>(i - 100, 4) - std::min<size_t>(i > 111 ? i - 111 : 0, 4));
	const auto m40 = OdometryBridge::distances(bent, s.odometry, 40), m12 = OdometryBridge::distances(bent, s.odometry, 12);
	EXPECT_LT(OdometryBridge::worst(m40), 3);
	EXPECT_TRUE(OdometryBridge::strays(m40, 40, 4).empty());
	EXPECT_GT(OdometryBridge::worst(m12), 4);
	const auto strays = OdometryBridge::strays(m12, 12, 4);
	ASSERT_FALSE(strays.empty());
	EXPECT_LE(strays.front().first, 100u);
	EXPECT_GE(strays.back().second, 115u);
	EXPECT_GT(strays.front().first, 60u);  // the straight path before it is no stray
}
