#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/MathCache.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

using namespace whiskermap::core;

namespace
{
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/** angleDiff as it was written before the fmod-free remainder (the reference). */
double angleDiffReference(double a, double b, double period)
{
	double d = a - b;
	if (d > -period / 2 && d <= period / 2) return d;
	d = std::fmod(d, period);
	if (d <= -period / 2) d += period;
	if (d > period / 2) d -= period;
	return d;
}
}  // namespace

TEST(MathCache, ReturnsExactlyWhatTheLibraryReturns)
{
	// Angle 0 first, before anything else can have filled its slot: an empty slot is not a
	// cached zero.
	for (const double a : {0.0, -0.0, 0.0})
	{
		const SinCos v = cachedSinCos(a);
		EXPECT_TRUE(sameBits(v.sin, std::sin(a)) && sameBits(v.cos, std::cos(a))) << a;
	}
	const double denormal = std::numeric_limits<double>::denorm_min();  // bits 1: never cached
	for (const double x : {1e-4, 1e-3, 7e3, 1e7, 0.02, 1.0, 0.0, -1.0, denormal, 1e300})
		for (int again = 0; again < 3; again++)  // first call fills the cache, the others hit it
			EXPECT_TRUE(sameBits(cachedLog(x), std::log(x))) << x;
	EXPECT_TRUE(std::isnan(cachedLog(std::numeric_limits<double>::quiet_NaN())));
	// More distinct angles than slots, twice over: replaced entries, then hits and misses.
	for (int round = 0; round < 2; round++)
		for (int i = -500; i <= 500; i++)
		{
			const double a = i * 0.0123;
			const SinCos v = cachedSinCos(a);
			EXPECT_TRUE(sameBits(v.sin, std::sin(a)) && sameBits(v.cos, std::cos(a))) << a;
		}
}

TEST(MathCache, ThreadsSharingTheCachesGetExactValues)
{
	std::vector<std::thread> threads;
	std::vector<int> wrong(4, 0);
	for (int t = 0; t < 4; t++)
		threads.emplace_back([t, &wrong] {
			for (int k = 0; k < 20000; k++)
			{
				const double a = (k % 97) * 0.031 + t * 1e-3, x = 1e-3 * (1 + k % 13);
				const SinCos v = cachedSinCos(a);
				wrong[t] += !sameBits(v.sin, std::sin(a)) || !sameBits(v.cos, std::cos(a)) ||
							!sameBits(cachedLog(x), std::log(x));
			}
		});
	for (auto& th : threads) th.join();
	for (int t = 0; t < 4; t++) EXPECT_EQ(wrong[t], 0) << "thread " << t;
}

TEST(Angles, DifferenceIsBitForBitTheFmodOne)
{
	for (const double period : {M_PI / 2, M_PI, 2 * M_PI})
		for (int i = -4000; i <= 4000; i++)
		{
			const double a = i * 0.01237, b = -i * 0.0041;  // differences up to about 21 periods
			EXPECT_TRUE(sameBits(angleDiff(a, b, period), angleDiffReference(a, b, period))) << a << " " << b;
		}
	EXPECT_TRUE(sameBits(angleDiff(-2 * M_PI, 0, M_PI), angleDiffReference(-2 * M_PI, 0, M_PI)));
	EXPECT_TRUE(std::isnan(angleDiff(std::numeric_limits<double>::infinity(), 0, M_PI)));
}
