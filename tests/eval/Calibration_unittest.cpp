#include "Fixtures.h"

#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/Calibration.h>

#include <cmath>

using namespace whiskermap;
using eval::Calibration;

namespace
{
/** Seven objects by hand: bin 0 {0.05 false}, bin 1 {0.15 false, 0.15 true}, bin 5 {0.5 true},
 *  bin 9 {0.95 true, 0.95 true, 1.0 false}. */
Calibration seven()
{
	Calibration c;
	c.add(0.05, false);
	c.add(0.15, false);
	c.add(0.15, true);
	c.add(0.5, true);
	c.add(0.95, true);
	c.add(0.95, true);
	c.add(1.0, false);
	return c;
}
}  // namespace

TEST(Calibration, BinsAndEceByHand)
{
	const auto c = seven();
	EXPECT_EQ(c.count(), 7u);
	EXPECT_EQ(c.real(), 4u);
	const auto& b = c.bins();
	EXPECT_EQ(b[0].count, 1u);
	EXPECT_EQ(b[1].count, 2u);
	EXPECT_EQ(b[5].count, 1u);
	EXPECT_EQ(b[9].count, 3u);
	for (size_t i : {2, 3, 4, 6, 7, 8}) EXPECT_EQ(b[i].count, 0u) << i;
	EXPECT_TRUE(std::isnan(b[2].meanExistence()));
	EXPECT_TRUE(std::isnan(b[2].fractionReal()));
	EXPECT_NEAR(b[1].meanExistence(), 0.15, 1e-12);
	EXPECT_NEAR(b[1].fractionReal(), 0.5, 1e-12);
	EXPECT_NEAR(b[9].meanExistence(), 2.9 / 3, 1e-12);
	EXPECT_NEAR(b[9].fractionReal(), 2.0 / 3, 1e-12);
	// ECE = (1 x 0.05 + 2 x 0.35 + 1 x 0.5 + 3 x |2/3 - 2.9/3|) / 7 = 2.15 / 7.
	EXPECT_NEAR(c.ece(), 2.15 / 7, 1e-12);
}

TEST(Calibration, EdgesEmptyAndRange)
{
	Calibration c;
	EXPECT_TRUE(std::isnan(c.ece()));
	c.add(0.1, true);  // a bin's lower edge belongs to it
	c.add(0.0, false);
	c.add(1.0, true);  // 1 goes to the last bin
	EXPECT_EQ(c.bins()[1].count, 1u);
	EXPECT_EQ(c.bins()[0].count, 1u);
	EXPECT_EQ(c.bins()[9].count, 1u);
	// Perfectly calibrated objects at 0 and 1 and one at 0.1 that is real: ECE = 0.9 / 3.
	EXPECT_NEAR(c.ece(), 0.3, 1e-12);
	EXPECT_THROW(c.add(-0.01, true), core::Error);
	EXPECT_THROW(c.add(1.01, true), core::Error);
	EXPECT_THROW(c.add(NAN, true), core::Error);
}

TEST(Calibration, PoolingAddsUp)
{
	Calibration a, b;
	a.add(0.05, false);
	a.add(0.15, false);
	a.add(0.15, true);
	b.add(0.5, true);
	b.add(0.95, true);
	b.add(0.95, true);
	b.add(1.0, false);
	a.add(b);
	EXPECT_EQ(a.count(), 7u);
	EXPECT_NEAR(a.ece(), seven().ece(), 1e-12);
	EXPECT_NE(a.ece(), b.ece());
}

TEST(Calibration, RealMeansMatchedOnceByTheMatcher)
{
	const std::vector<world::Table> truth{test::table(1, 1, 0), test::table(4, 1, 0)};
	auto row = [](double x, double y, double existence) {
		eval::TableCsv::MapRow r;
		r.table = test::table(x, y, 0);
		r.existence = existence;
		return r;
	};
	// Two estimates of true table 0 (only the nearer one is real: a true object matches at
	// most once), one far from any (not real), one of true table 1 turned 90 deg (gated out).
	const std::vector<eval::TableCsv::MapRow> objects{
		row(1.1, 1, 0.62), row(1.01, 1, 0.91), row(2.5, 3, 0.35),
		[&] { auto r = row(4, 1, 0.75); r.table.yaw = M_PI / 2; return r; }()};
	const auto c = Calibration::of(truth, objects, eval::EvalOptions());
	EXPECT_EQ(c.count(), 4u);
	EXPECT_EQ(c.real(), 1u);
	EXPECT_EQ(c.bins()[9].real, 1u);
	EXPECT_EQ(c.bins()[6].real, 0u);
	EXPECT_EQ(c.bins()[7].real, 0u);
	EXPECT_EQ(c.bins()[3].real, 0u);
	// ECE = (0.09 + 0.62 + 0.35 + 0.75) / 4.
	EXPECT_NEAR(c.ece(), (0.09 + 0.62 + 0.35 + 0.75) / 4, 1e-12);
}

TEST(Calibration, JsonAndText)
{
	const auto c = seven();
	const auto j = c.toJson(0);
	EXPECT_NE(j.find("\"objects\": 7,\n  \"real\": 4,\n  \"ece\": 0.307143,"), std::string::npos) << j;
	EXPECT_NE(j.find("{\"lo\": 0.100000, \"hi\": 0.200000, \"count\": 2, \"real\": 1, \"mean_existence\": 0.150000, \"fraction_real\": 0.500000},"), std::string::npos) << j;
	EXPECT_NE(j.find("\"count\": 0, \"real\": 0, \"mean_existence\": null, \"fraction_real\": null}"), std::string::npos) << j;
	const auto t = c.toText();
	EXPECT_NE(t.find("calibration: 7 objects, 4 real; ECE 0.307143"), std::string::npos) << t;
	EXPECT_NE(t.find("[0.9, 1.0]       3       2        0.966667       0.666667"), std::string::npos) << t;
}
