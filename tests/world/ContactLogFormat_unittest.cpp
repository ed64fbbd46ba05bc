#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/world/ContactLogFormat.h>

#include <cmath>
#include <cstring>
#include <random>

using whiskermap::world::ContactLogFormat;

namespace
{
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

double degreesBack(double radians)
{
	std::string s;
	ContactLogFormat::appendDegrees(s, radians);
	double back = 0;
	EXPECT_EQ(ContactLogFormat::parseDegrees(s, back), nullptr) << s;
	return back;
}

mrpt::Clock::time_point timeOf(const std::string& s)
{
	mrpt::Clock::time_point t;
	const char* why = ContactLogFormat::parseTime(s, t);
	EXPECT_EQ(why, nullptr) << s << ": " << (why ? why : "");
	return t;
}

int64_t unixTicks(const std::string& s)
{
	return timeOf(s).time_since_epoch().count() - INT64_C(116444736000000000);
}
}  // namespace

TEST(ContactLogFormat, EveryRadianValueSurvivesDegreesText)
{
	std::mt19937_64 rng(1);
	std::uniform_real_distribution<double> angle(-7, 7), exponent(-300, 300);
	std::uniform_int_distribution<uint64_t> bits;
	for (int i = 0; i < 200000; i++)
	{
		double r = angle(rng);
		if (i % 4 == 1) r = std::ldexp(angle(rng), int(exponent(rng)) / 3);	 // tiny and large
		if (i % 4 == 2)														 // any finite double
		{
			const uint64_t b = bits(rng);
			std::memcpy(&r, &b, sizeof r);
			if (!std::isfinite(r) || std::abs(r) > 1e300) continue;
		}
		ASSERT_TRUE(sameBits(degreesBack(r), r)) << r;
	}
	for (int d = -720; d <= 720; d++)
	{
		const double r = whiskermap::core::deg2rad(d);
		for (double v : {r, std::nextafter(r, 10.0), std::nextafter(r, -10.0)})
			ASSERT_TRUE(sameBits(degreesBack(v), v)) << v;
	}
	EXPECT_TRUE(sameBits(degreesBack(-0.0), -0.0));
	EXPECT_TRUE(sameBits(degreesBack(0.0), 0.0));
}

TEST(ContactLogFormat, DoublePrecisionDegreesCouldNotBeExact)
{
	// Why the reader works in long double: with the degree value held in a double, some
	// radian values are reachable from no text at all. Find one.
	std::mt19937_64 rng(2);
	std::uniform_real_distribution<double> angle(1.9, 2.0);	 // 109-115 deg: coarse degree spacing
	int unreachable = 0;
	for (int i = 0; i < 1000 && unreachable == 0; i++)
	{
		const double r = angle(rng);
		const double d = r * 57.29577951308232;
		bool hit = false;
		for (double c = std::nextafter(d, 0.0), k = 0; k < 3; k++, c = std::nextafter(c, 1e9))
			hit = hit || sameBits(c * 0.017453292519943295, r);
		unreachable += !hit;
	}
	EXPECT_GT(unreachable, 0);
}

TEST(ContactLogFormat, RoundDegreesStayShort)
{
	for (const char* text : {"0", "10", "170", "-170", "-90", "180", "-180", "45"})
	{
		double r = 0;
		ASSERT_EQ(ContactLogFormat::parseDegrees(text, r), nullptr);
		std::string s;
		ContactLogFormat::appendDegrees(s, r);
		EXPECT_EQ(s, text);
	}
	double r = 0;
	ASSERT_EQ(ContactLogFormat::parseDegrees("+1.5e1", r), nullptr);
	EXPECT_NEAR(r, whiskermap::core::deg2rad(15), 1e-16);
}

TEST(ContactLogFormat, TimesAreExactTo100Nanoseconds)
{
	EXPECT_EQ(unixTicks("1300000000"), INT64_C(13000000000000000));
	EXPECT_EQ(unixTicks("0"), 0);
	EXPECT_EQ(unixTicks("0.000"), 0);
	EXPECT_EQ(unixTicks("1.5"), 15000000);
	EXPECT_EQ(unixTicks("-1.5"), -15000000);
	EXPECT_EQ(unixTicks("1e3"), INT64_C(10000000000));
	EXPECT_EQ(unixTicks("0.00000005"), 1);	// half a tick rounds up
	EXPECT_EQ(unixTicks("0.0000000499"), 0);
	EXPECT_EQ(unixTicks("1699999999.123456789"), INT64_C(16999999991234568));  // ROS stamp
	EXPECT_EQ(timeOf("1300000003"), mrpt::Clock::fromDouble(1300000003.0));

	std::mt19937_64 rng(3);
	std::uniform_int_distribution<int64_t> ticks(0, INT64_C(1) << 62);
	for (int i = 0; i < 100000; i++)
	{
		const mrpt::Clock::time_point t{mrpt::Clock::duration(ticks(rng))};
		std::string s;
		ContactLogFormat::appendTime(s, t);
		ASSERT_EQ(timeOf(s), t) << s;
	}
}

TEST(ContactLogFormat, BadValuesSayWhy)
{
	mrpt::Clock::time_point t;
	EXPECT_STREQ(ContactLogFormat::parseTime("", t), "is empty");
	EXPECT_STREQ(ContactLogFormat::parseTime("abc", t), "is not a number");
	EXPECT_STREQ(ContactLogFormat::parseTime("1.2.3", t), "is not a number");
	EXPECT_STREQ(ContactLogFormat::parseTime("nan", t), "is not a number");
	EXPECT_STREQ(
		ContactLogFormat::parseTime("1e30", t), "is out of range (before 1601 or after 30000)");
	EXPECT_STREQ(
		ContactLogFormat::parseTime("-20000000000", t),
		"is out of range (before 1601 or after 30000)");
	EXPECT_STREQ(
		ContactLogFormat::parseTime("1.2345678901234567891", t),
		"has more than 19 significant digits");
	double v = 0;
	EXPECT_EQ(ContactLogFormat::parseNumber("+0.5", v), nullptr);
	EXPECT_EQ(v, 0.5);
	EXPECT_STREQ(ContactLogFormat::parseNumber("", v), "is empty");
	EXPECT_STREQ(ContactLogFormat::parseNumber("nan", v), "is not finite");
	EXPECT_STREQ(ContactLogFormat::parseNumber("-inf", v), "is not finite");
	EXPECT_STREQ(ContactLogFormat::parseNumber("1e999", v), "is out of range");
	EXPECT_STREQ(ContactLogFormat::parseNumber("0x10", v), "is not a number");
	EXPECT_STREQ(ContactLogFormat::parseNumber("+-1", v), "is not a number");
	EXPECT_STREQ(ContactLogFormat::parseNumber("1 m", v), "is not a number");
	EXPECT_STREQ(ContactLogFormat::parseDegrees("NaN", v), "is not finite");
	EXPECT_STREQ(ContactLogFormat::parseDegrees("90deg", v), "is not a number");
	EXPECT_STREQ(ContactLogFormat::parseDegrees("1e5000", v), "is out of range");
}
