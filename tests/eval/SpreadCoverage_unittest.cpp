// eval::SpreadCoverage: do the reported pose spreads cover the truth? Hand values.
#include <gtest/gtest.h>
#include <whiskermap/eval/SpreadCoverage.h>

#include <cmath>

using namespace whiskermap;
using eval::SpreadCoverage;

TEST(SpreadCoverage, FractionsWithinAndRmsByHand)
{
	SpreadCoverage c;
	EXPECT_TRUE(std::isnan(c.within(0, 1)));
	EXPECT_TRUE(std::isnan(c.rmsZ(2)));
	c.add({0.001, -0.003, 0.0}, {0.002, 0.002, 0.01});  // z = 0.5, 1.5, 0
	c.add({-0.004, 0.001, 0.03}, {0.002, 0.002, 0.01});  // z = 2, 0.5, 3
	EXPECT_EQ(c.count(), 2u);
	EXPECT_EQ(c.within(0, 1), 0.5);  // x: 0.5 in, 2 out
	EXPECT_EQ(c.within(0, 2), 1.0);  // 2 sd exactly counts as within
	EXPECT_EQ(c.within(1, 1), 0.5);
	EXPECT_EQ(c.within(1, 2), 1.0);
	EXPECT_EQ(c.within(2, 2), 0.5);
	EXPECT_NEAR(c.rmsZ(0), std::sqrt((0.25 + 4) / 2), 1e-12);
	EXPECT_NEAR(c.rmsZ(2), std::sqrt(9.0 / 2), 1e-12);
	SpreadCoverage d;
	d.add({0, 0, 0}, {0, 0, 0});  // a zero sd covers only a zero error
	d.add({0.001, 0, 0}, {0, 1, 1});
	EXPECT_EQ(d.within(0, 2), 0.5);
	EXPECT_TRUE(std::isinf(d.rmsZ(0)));
	c.add(d);
	EXPECT_EQ(c.count(), 4u);
	EXPECT_EQ(c.axes()[1].within1, 3u);  // y: 1.5 out; 0.5, 0 / 0 and 0 / 1 in
}

TEST(SpreadCoverage, MatchedObjectsOnlyAndYawModuloTheSymmetry)
{
	const world::Table a{0, 0, 0.1, 1.0, 0.6, 0.05, 0.7}, b{5, 5, 0, 1.0, 0.6, 0.05, 0.7};
	std::vector<eval::TableCsv::MapRow> rows(3);
	rows[0].table = a, rows[0].table.x += 0.003, rows[0].table.yaw += M_PI;  // the same table turned by 180
	rows[0].spread = eval::TableCsv::MapRow::Spread{0.002, 0.001, 1.0};
	rows[1].table = b, rows[1].table.y -= 0.001;  // no spread column: skipped
	rows[2].table = {9, 9, 0, 1.0, 0.6, 0.05, 0.7};  // matches nothing
	rows[2].spread = eval::TableCsv::MapRow::Spread{0.002, 0.001, 1.0};
	const SpreadCoverage c = SpreadCoverage::of({a, b}, rows, eval::EvalOptions{});
	ASSERT_EQ(c.count(), 1u);
	EXPECT_NEAR(c.rmsZ(0), 1.5, 1e-9);
	EXPECT_NEAR(c.rmsZ(1), 0.0, 1e-9);
	EXPECT_NEAR(c.rmsZ(2), 0.0, 1e-9);
	EXPECT_EQ(c.toText(),
			  "pose spread: 1 matched objects; fraction within 1 / 2 sd, rms error / sd\n"
			  "  x    0.000000 / 1.000000, 1.500000\n"
			  "  y    1.000000 / 1.000000, 0.000000\n"
			  "  yaw  1.000000 / 1.000000, 0.000000\n");
	EXPECT_NE(c.toJson(0).find("\"yaw\": {\"within_1sd\": 1.000000, \"within_2sd\": 1.000000, \"rms_z\": 0.000000}"),
			  std::string::npos);
}
