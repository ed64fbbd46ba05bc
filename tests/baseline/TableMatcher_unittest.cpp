#include "HandMade.h"

#include <gtest/gtest.h>
#include <whiskermap/baseline/FreeSpace.h>
#include <whiskermap/baseline/LegExtraction.h>
#include <whiskermap/baseline/TableMatcher.h>
#include <whiskermap/core/Angles.h>

using namespace whiskermap;

namespace
{
const baseline::TBaselineParams P;

/** A sweep whose one whisker (0.6 m) turned almost a full circle at `where` touching nothing. */
obs::RawlogReader::Sweep emptyWhisk(const Eigen::Vector2d& where)
{
	auto o = std::make_shared<obs::CObservationWhiskerContacts>();
	obs::TWhisker w;
	w.sweep_start = core::deg2rad(-179), w.sweep_end = core::deg2rad(179), w.length = 0.6;
	w.angle = w.sweep_end;
	o->whiskers = {w};
	return {mrpt::poses::CPose2D(where.x(), where.y(), 0), o};
}

/** The sectors the sweeps swept. */
std::vector<obs::SweptSector> swept(const std::vector<obs::RawlogReader::Sweep>& sweeps)
{
	std::vector<obs::SweptSector> out;
	for (const auto& s : sweeps)
		for (const auto& sector : s.obs->toSweptSectors(s.robotPose)) out.push_back(sector);
	return out;
}

std::vector<baseline::TableEstimate> match(
	const std::vector<baseline::Contact>& contacts, const std::vector<obs::RawlogReader::Sweep>& sweeps = {})
{
	const auto legs = baseline::LegExtraction::run(contacts, P);
	const baseline::FreeSpace free(swept(sweeps));
	return baseline::TableMatcher(contacts, legs.legs, free, P).run();
}
}  // namespace

TEST(TableMatcher, OneTableFromItsFourLegs)
{
	const Eigen::Vector2d centre(2.0, 1.5);
	const double yaw = core::deg2rad(35);
	const auto tables = match(handmade::table(centre, yaw));
	ASSERT_EQ(tables.size(), 1u);
	EXPECT_EQ(tables[0].legCount(), 4);
	EXPECT_NEAR((tables[0].centre - centre).norm(), 0, 1e-6);
	EXPECT_NEAR(core::angleDiff(tables[0].yaw, yaw, M_PI), 0, 1e-6);
	EXPECT_EQ(tables[0].contacts, 4u * 20u);
}

TEST(TableMatcher, OneLegIsNoTable)
{
	EXPECT_TRUE(match(handmade::table({2, 2}, 0, {0})).empty());
}

TEST(TableMatcher, LegsAtTheWrongSpacingAreNoTable)
{
	auto contacts = handmade::leg({0, 0}, 0);
	const auto other = handmade::leg({0.8, 0}, 0);  // neither 0.6, 1.0 nor 1.17 m away
	contacts.insert(contacts.end(), other.begin(), other.end());
	EXPECT_TRUE(match(contacts).empty());
}

TEST(TableMatcher, FreeSpaceTellsATwoLegTableFromItsMirror)
{
	// Legs 0 (2.5, 2.3) and 1 (1.5, 2.3) of a table at (2, 2): the mirror table at (2, 2.6)
	// would have legs at (2.5, 2.9) and (1.5, 2.9).
	const auto contacts = handmade::table({2, 2}, 0, {0, 1});
	const auto sweptMirror = match(contacts, {emptyWhisk({2, 2.9})});
	ASSERT_EQ(sweptMirror.size(), 1u);
	EXPECT_NEAR((sweptMirror[0].centre - Eigen::Vector2d(2, 2)).norm(), 0, 1e-6);
	EXPECT_EQ(sweptMirror[0].legCount(), 2);
	const auto sweptTruth = match(contacts, {emptyWhisk({2, 1.7})});  // through the true legs 2, 3
	ASSERT_EQ(sweptTruth.size(), 1u);
	EXPECT_NEAR((sweptTruth[0].centre - Eigen::Vector2d(2, 2.6)).norm(), 0, 1e-6);
	EXPECT_TRUE(match(contacts, {emptyWhisk({2, 1.7}), emptyWhisk({2, 2.9})}).empty());
}

TEST(FreeSpace, DepthInsideASweptSector)
{
	const baseline::FreeSpace free(swept({emptyWhisk({0, 0})}));
	EXPECT_EQ(free.sectors(), 1u);
	EXPECT_NEAR(free.depth({0.5, 0}), 0.1, 1e-9);  // 0.1 m inside the reach
	EXPECT_NEAR(free.depth({0.2, 0}), 0.2, 1e-9);  // the pivot is 0.2 m away
	EXPECT_EQ(free.depth({0.7, 0}), 0.0);  // out of reach
	EXPECT_EQ(free.depth({-0.3, 0}), 0.0);  // the 2 degrees the whisker never turned through
	EXPECT_LT(free.depth({-0.3, 0.01}), 0.01);
}
