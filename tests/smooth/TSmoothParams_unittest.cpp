#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/smooth/TSmoothParams.h>

#include "../TempDirTest.h"

#include <cmath>
#include <fstream>

using namespace whiskermap;

namespace
{
class TSmoothParamsTest : public test::TempDirTest
{
   protected:
	std::string ini(const std::string& text)
	{
		const std::string p = path("s.ini");
		std::ofstream(p) << text;
		return p;
	}
};
}  // namespace

TEST_F(TSmoothParamsTest, DefaultsWithoutTheSectionAndEveryKeyRead)
{
	const auto d = smooth::TSmoothParams::load(ini("[slam]\nparticles = 3\n"));
	EXPECT_TRUE(d.enabled);
	EXPECT_EQ(d.passes, smooth::TSmoothParams().passes);
	const auto p = smooth::TSmoothParams::load(ini(
		"[smooth]\nenabled = false\ngate = 0.1\nnormal_gate_deg = 30\nposition_floor = 0.003\nhuber = 1.5\n"
		"solid_sigma = 2\nrounds = 3\niterations = 7\npasses = 2\nduplicate_sigma = 0.01\nduplicate_shrink = 0.2\n"
		"duplicate_distance = 0.05\nduplicate_wall_distance = 0.2\ntable_sigma = 0.004\n"
		"bridge_gate = 6\nbridge_window = 30\nbridge_short_window = 12\nstretch_margin = 0\n"));
	EXPECT_FALSE(p.enabled);
	EXPECT_DOUBLE_EQ(p.gate, 0.1);
	EXPECT_NEAR(p.normal_gate, M_PI / 6, 1e-12);
	EXPECT_DOUBLE_EQ(p.position_floor, 0.003);
	EXPECT_DOUBLE_EQ(p.huber, 1.5);
	EXPECT_DOUBLE_EQ(p.solid_sigma, 2);
	EXPECT_EQ(p.rounds, 3u);
	EXPECT_EQ(p.iterations, 7u);
	EXPECT_EQ(p.passes, 2u);
	EXPECT_DOUBLE_EQ(p.duplicate_sigma, 0.01);
	EXPECT_DOUBLE_EQ(p.duplicate_shrink, 0.2);
	EXPECT_DOUBLE_EQ(p.duplicate_distance, 0.05);
	EXPECT_DOUBLE_EQ(p.duplicate_wall_distance, 0.2);
	EXPECT_DOUBLE_EQ(p.table_sigma, 0.004);
	EXPECT_EQ(d.table_sigma, 0);  // off unless asked for
	EXPECT_DOUBLE_EQ(p.bridge_gate, 6);
	EXPECT_EQ(p.bridge_window, 30u);
	EXPECT_DOUBLE_EQ(d.bridge_gate, 4);  // on unless turned off
	EXPECT_EQ(d.bridge_window, 40u);
	EXPECT_EQ(p.bridge_short_window, 12u);
	EXPECT_EQ(d.bridge_short_window, 0u);  // off unless asked for
	EXPECT_EQ(p.stretch_margin, 0u);
	EXPECT_EQ(d.stretch_margin, 40u);  // on unless turned off
}

TEST_F(TSmoothParamsTest, BadValuesAndUnknownKeysNameTheFileAndKey)
{
	try
	{
		smooth::TSmoothParams::load(ini("[smooth]\ngate = -1\n"));
		FAIL() << "no error";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("s.ini: line 2: [smooth] gate"), std::string::npos) << e.what();
	}
	try
	{
		smooth::TSmoothParams::load(ini("[smooth]\ngates = 0.1\n"));
		FAIL() << "no error";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("[smooth] gates: unknown key"), std::string::npos) << e.what();
	}
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\npasses = 0\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\ntable_sigma = -0.01\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nbridge_gate = -1\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nbridge_window = 0\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nbridge_window = 1001\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nbridge_short_window = 1001\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nbridge_short_window = -1\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nstretch_margin = 1001\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(ini("[smooth]\nstretch_margin = -1\n")), core::Error);
	EXPECT_THROW(smooth::TSmoothParams::load(path("missing.ini")), core::Error);
}

// config/whisker-slam-100.ini (100 particles in batches of 4) smooths as config/whisker-slam.ini,
// but with eq. S7 on (doc/slam.md, "Tables keep their shape": with 30 particles it costs map
// F1 on random_yaw1).
TEST(TSmoothParams, HundredParticleConfigSmoothsAsTheShippedOneWithTheTablesShapes)
{
	const std::string src = WHISKERMAP_SOURCE_DIR;
	const auto s = smooth::TSmoothParams::load(src + "/config/whisker-slam.ini");
	const auto t = smooth::TSmoothParams::load(src + "/config/whisker-slam-100.ini");
	EXPECT_EQ(s.enabled, t.enabled);
	EXPECT_EQ(s.gate, t.gate);
	EXPECT_EQ(s.normal_gate, t.normal_gate);
	EXPECT_EQ(s.position_floor, t.position_floor);
	EXPECT_EQ(s.huber, t.huber);
	EXPECT_EQ(s.wall_merge, t.wall_merge);
	EXPECT_EQ(s.duplicate_sigma, t.duplicate_sigma);
	EXPECT_EQ(s.duplicate_shrink, t.duplicate_shrink);
	EXPECT_EQ(s.duplicate_distance, t.duplicate_distance);
	EXPECT_EQ(s.duplicate_wall_distance, t.duplicate_wall_distance);
	EXPECT_EQ(s.solid_sigma, t.solid_sigma);
	EXPECT_EQ(s.rounds, t.rounds);
	EXPECT_EQ(s.iterations, t.iterations);
	EXPECT_EQ(s.passes, t.passes);
	EXPECT_EQ(s.bridge_gate, t.bridge_gate);
	EXPECT_EQ(s.bridge_window, t.bridge_window);
	EXPECT_EQ(s.bridge_short_window, t.bridge_short_window);
	EXPECT_EQ(s.bridge_short_window, 0u);
	EXPECT_EQ(s.stretch_margin, t.stretch_margin);
	EXPECT_EQ(s.table_sigma, 0);
	EXPECT_EQ(t.table_sigma, 0.005);
}
