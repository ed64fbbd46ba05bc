#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/obs/Shapelet.h>
#include <whiskermap/maps/TableConsolidator.h>

using namespace whiskermap;
using core::deg2rad;

namespace
{
world::Table table(double x, double y, double yawDeg)
{
	return world::Table{x, y, deg2rad(yawDeg), 1.0, 0.6, 0.05, 0.7};
}
}  // namespace

TEST(TableConsolidator, MergesAgreeingTablesAndAveragesModulo180)
{
	maps::TableConsolidator c;
	c.addPose({table(1.0, 1.0, 89)}, {});
	c.addPose({table(1.1, 1.0, -89)}, {});  // same orientation as 91 deg
	ASSERT_EQ(c.objects().size(), 1u);
	const auto& o = c.objects()[0];
	EXPECT_EQ(o.support, 2u);
	EXPECT_NEAR(o.table.x, 1.05, 1e-12);
	EXPECT_NEAR(std::abs(core::angleDiff(o.table.yaw, deg2rad(90), M_PI)), 0, 1e-9);
}

TEST(TableConsolidator, KeepsTablesApartBeyondEitherGate)
{
	maps::TableConsolidator c;  // defaults: 0.15 m, 15 deg
	c.addPose({table(1.0, 1.0, 0)}, {});
	c.addPose({table(1.2, 1.0, 0)}, {});  // too far
	c.addPose({table(1.0, 1.0, 30)}, {});  // turned too much
	c.addPose({table(1.0, 1.05, 175)}, {});  // = -5 deg: merges with the first
	ASSERT_EQ(c.objects().size(), 3u);
	EXPECT_EQ(c.objects()[0].support, 2u);
}

TEST(TableConsolidator, OnePoseCannotSupportAnObjectTwice)
{
	maps::TableConsolidator c;
	c.addPose({table(1.0, 1.0, 0), table(1.05, 1.0, 0)}, {});
	EXPECT_EQ(c.objects().size(), 2u);
	for (const auto& o : c.objects()) EXPECT_LE(o.support, o.evidence);
}

TEST(TableConsolidator, ContactsOnALegWithoutTheTableLowerExistence)
{
	maps::TableConsolidator c;
	const auto t = table(1.0, 1.0, 0);
	c.addPose({t}, {});
	const auto leg = t.legCentre(0);
	obs::Shapelet onLeg{leg.x() + 0.025, leg.y(), 0, 0.7, 0};
	obs::Shapelet elsewhere{3.0, 3.0, 0, 0.7, 1};
	c.addPose({}, {onLeg});  // evidence, not found: counts against it
	c.addPose({}, {elsewhere});  // no evidence: does not count
	ASSERT_EQ(c.objects().size(), 1u);
	EXPECT_EQ(c.objects()[0].support, 1u);
	EXPECT_EQ(c.objects()[0].evidence, 2u);
	EXPECT_DOUBLE_EQ(c.objects()[0].existence(), 0.5);
}

// Regression (issue 8): cells were 32-bit ints (a loop to INT_MAX never ended near
// x = 2^31 m) and the cell key shifted a negative value left (undefined behaviour).
TEST(TableConsolidator, FarAndNegativeCoordinatesMergeAndEnd)
{
	for (const double x : {-3.5, 2147483647.5, -2147483648.5, 4.3e9, 1e15, -1e300})
	{
		maps::TableConsolidator c;
		c.addPose({table(x, -x, 0)}, {obs::Shapelet{x + 0.5, -x + 0.3, 0, 0.7, 0}});
		c.addPose({table(x, -x, 0)}, {});
		ASSERT_EQ(c.objects().size(), 1u) << x;
		EXPECT_EQ(c.objects()[0].support, 2u) << x;
	}
}
