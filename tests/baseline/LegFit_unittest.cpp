#include "HandMade.h"

#include <gtest/gtest.h>
#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/baseline/LegExtraction.h>
#include <whiskermap/baseline/LegFit.h>
#include <whiskermap/core/Angles.h>

#include <numeric>

using namespace whiskermap;
using baseline::Contact;

namespace
{
std::vector<size_t> all(const std::vector<Contact>& c)
{
	std::vector<size_t> ids(c.size());
	std::iota(ids.begin(), ids.end(), 0);
	return ids;
}
}  // namespace

TEST(LegFit, RecoversALegFromContactsOnItsFaces)
{
	const baseline::TBaselineParams p;
	const Eigen::Vector2d centre(1.2, -0.4);
	const double yaw = core::deg2rad(20);
	const auto contacts = handmade::leg(centre, yaw);
	const auto leg = baseline::LegFit::fit(contacts, all(contacts), p);
	EXPECT_NEAR((leg.centre - centre).norm(), 0, 1e-6);
	EXPECT_NEAR(leg.yaw, yaw, 1e-6);
	EXPECT_EQ(leg.faces, 4);
	EXPECT_EQ(leg.outliers, 0u);
	EXPECT_TRUE(leg.legShaped(p));
	EXPECT_NEAR(leg.texture, 0.7, 1e-12);
}

TEST(LegFit, YawIsModuloAQuarterTurn)
{
	const baseline::TBaselineParams p;
	const auto contacts = handmade::leg({0, 0}, core::deg2rad(100), {0, 1});
	const auto leg = baseline::LegFit::fit(contacts, all(contacts), p);
	EXPECT_NEAR(leg.yaw, core::deg2rad(10), 1e-6);  // 100 deg = 10 deg for a square
	EXPECT_NEAR(leg.centre.norm(), 0, 1e-6);  // two adjacent faces pin the centre
}

TEST(LegFit, OneFacePinsTheCentreAcrossTheFaceOnly)
{
	const baseline::TBaselineParams p;
	const Eigen::Vector2d centre(2, 3);
	auto contacts = handmade::leg(centre, 0, {0}, 1);  // face 0 (normal +x), at its middle
	contacts.push_back(contacts[0]);
	contacts.back().shaft = {-1, 0};
	const auto leg = baseline::LegFit::fit(contacts, all(contacts), p);
	EXPECT_NEAR(leg.centre.x(), 2, 1e-6);
	EXPECT_NEAR(leg.centre.y(), 3, 1e-6);  // the prior: where the contacts point
	EXPECT_GT(leg.centreCovariance(1, 1), 100 * leg.centreCovariance(0, 0));
	// Contacts along the whole face pin it along the face too: it cannot be shorter.
	const auto spread = handmade::leg(centre, 0, {0}, 5);
	const auto pinned = baseline::LegFit::fit(spread, all(spread), p);
	EXPECT_LT(pinned.centreCovariance(1, 1), leg.centreCovariance(1, 1) / 100);
}

TEST(LegFit, ContactsOfTwoLegsAreNotOneLeg)
{
	const baseline::TBaselineParams p;
	auto contacts = handmade::leg({0, 0}, 0);
	const auto other = handmade::leg({0.3, 0}, 0);
	contacts.insert(contacts.end(), other.begin(), other.end());
	EXPECT_FALSE(baseline::LegFit::fit(contacts, all(contacts), p).legShaped(p));
}

TEST(FaceResidual, UsesTheNoiseAlongTheShaft)
{
	baseline::TBaselineParams p;
	p.position_floor = 1e-9;
	Contact c;
	c.p = {0.025 + 0.01, 0};  // 1 cm outside face 0 of a leg at the origin
	c.normal = 0;
	c.sigma_r = 0.01;
	c.shaft = {-1, 0};  // head-on: the whole radial noise falls across the face
	EXPECT_NEAR(baseline::FaceResidual::on(c, {0, 0}, 0, 0, p).point, 1.0, 1e-6);
	c.shaft = Eigen::Vector2d(-std::cos(1.0), std::sin(1.0));  // oblique: less of it does
	EXPECT_NEAR(baseline::FaceResidual::on(c, {0, 0}, 0, 0, p).point, 1.0 / std::cos(1.0), 1e-6);
	EXPECT_EQ(baseline::FaceResidual::best(c, {0, 0}, 0, p).face, 0);
}

TEST(LegExtraction, AWallRunIsNotALeg)
{
	const baseline::TBaselineParams p;
	auto contacts = handmade::leg({1, 1}, core::deg2rad(30));
	// 1 m of wall at y = 0 touched every 2 cm, normal +y, with the tables' own texture: only
	// its shape tells it from a leg.
	for (int i = 0; i <= 50; i++)
	{
		Contact c;
		c.p = {0.5 + 0.02 * i, 0};
		c.normal = M_PI / 2;
		c.texture = 0.7;
		c.shaft = {0, -1};
		contacts.push_back(c);
	}
	const auto legs = baseline::LegExtraction::run(contacts, p);
	ASSERT_EQ(legs.legs.size(), 1u);
	EXPECT_NEAR((legs.legs[0].centre - Eigen::Vector2d(1, 1)).norm(), 0, 1e-6);
	EXPECT_EQ(legs.clustersRejected, 1u);
	EXPECT_EQ(legs.contactsRejected, 51u);
}

TEST(LegExtraction, WallTextureIsGatedOut)
{
	const baseline::TBaselineParams p;
	auto contacts = handmade::leg({1, 1}, 0);
	const auto wall = handmade::leg({3, 1}, 0, {0, 1, 2, 3}, 5, 0.05, 0.3);  // leg-shaped, wall texture
	contacts.insert(contacts.end(), wall.begin(), wall.end());
	const auto legs = baseline::LegExtraction::run(contacts, p);
	ASSERT_EQ(legs.legs.size(), 1u);
	EXPECT_EQ(legs.textureRejected, wall.size());
}

TEST(LegExtraction, SplitsTwoLegsTheLinkageJoined)
{
	const baseline::TBaselineParams p;
	auto contacts = handmade::leg({0, 0}, 0);
	const auto other = handmade::leg({0.07, 0}, 0);  // 2 cm apart: one single-linkage cluster
	contacts.insert(contacts.end(), other.begin(), other.end());
	const auto legs = baseline::LegExtraction::run(contacts, p);
	ASSERT_EQ(legs.legs.size(), 2u);
	EXPECT_EQ(legs.splits, 1u);
	const double xa = legs.legs[0].centre.x(), xb = legs.legs[1].centre.x();
	EXPECT_NEAR(std::min(xa, xb), 0, 1e-6);
	EXPECT_NEAR(std::max(xa, xb), 0.07, 1e-6);
}
