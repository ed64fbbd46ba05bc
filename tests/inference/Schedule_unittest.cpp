#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/inference/ShapeletMemory.h>

using namespace whiskermap;
using inference::AnnealingSchedule;
using inference::SamplerParams;

TEST(ShapeletMemory, KeepsTheMostRecent)
{
	inference::ShapeletMemory m(3);
	for (int i = 0; i < 5; i++) m.add(obs::Shapelet{double(i), 0, 0, 0, i});
	ASSERT_EQ(m.shapelets().size(), 3u);
	EXPECT_EQ(m.shapelets().front().x, 2);  // oldest kept first
	EXPECT_EQ(m.shapelets().back().x, 4);
	m.add(std::vector<obs::Shapelet>{{7, 0, 0, 0, 0}, {8, 0, 0, 0, 0}});
	EXPECT_EQ(m.shapelets().front().x, 4);
	EXPECT_EQ(inference::ShapeletMemory().capacity(), 7u);  // the paper's N
	EXPECT_THROW(inference::ShapeletMemory(0), core::Error);
}

TEST(AnnealingSchedule, Geometric)
{
	const auto s = AnnealingSchedule::geometric(0.1, 10, 5);
	ASSERT_EQ(s.size(), 5u);
	EXPECT_NEAR(s[0], 0.1, 1e-12);
	EXPECT_NEAR(s[1], 0.1 * std::sqrt(10.0), 1e-12);
	EXPECT_NEAR(s[2], 1.0, 1e-12);
	EXPECT_EQ(s[4], 10.0);
	EXPECT_EQ(AnnealingSchedule::geometric(0.1, 3, 1).betas(), std::vector<double>{3});
	EXPECT_THROW(AnnealingSchedule({}), core::Error);
	EXPECT_THROW(AnnealingSchedule({1, 0.5}), core::Error);  // must cool, not heat
	EXPECT_THROW(AnnealingSchedule({0, 1}), core::Error);
}

TEST(SamplerParams, ShippedConfigEqualsBuiltInDefaults)
{
	mrpt::config::CConfigFile cfg(WHISKERMAP_SOURCE_DIR "/config/whisker-map.ini");
	core::IniSection sec(cfg, "MetricMap_hierarchicalObjectMap_00_sampler", "whisker-map.ini");
	const SamplerParams f = SamplerParams::fromIni(sec), d;
	EXPECT_EQ(f.r1, d.r1);
	EXPECT_EQ(f.r2, d.r2);
	EXPECT_EQ(f.r3, d.r3);
	EXPECT_EQ(f.r4, d.r4);
	EXPECT_EQ(f.schedule.betas(), d.schedule.betas());
	EXPECT_EQ(f.sweeps_per_temperature, d.sweeps_per_temperature);
	EXPECT_EQ(f.coldest_sweeps, d.coldest_sweeps);
	EXPECT_EQ(f.polish_sweeps, d.polish_sweeps);
	EXPECT_EQ(f.existing_leg_probability, d.existing_leg_probability);
	EXPECT_EQ(f.merge_probability, d.merge_probability);
	EXPECT_EQ(f.leg_position_noise, d.leg_position_noise);
	EXPECT_EQ(f.leg_angle_noise, d.leg_angle_noise);
	EXPECT_EQ(f.acceptance, d.acceptance);
	EXPECT_EQ(f.proposals, d.proposals);
}

TEST(SamplerParams, BadKeysFail)
{
	mrpt::config::CConfigFile shipped(WHISKERMAP_SOURCE_DIR "/config/whisker-map.ini");
	std::string text = "[sampler]\n";
	std::vector<std::string> keys;
	shipped.getAllKeys("MetricMap_hierarchicalObjectMap_00_sampler", keys);
	for (const auto& k : keys) text += k + "=" + shipped.read_string("MetricMap_hierarchicalObjectMap_00_sampler", k, "") + "\n";
	const auto load = [](const std::string& t) {
		mrpt::config::CConfigFileMemory cfg(t);
		core::IniSection sec(cfg, "sampler", "test.ini");
		return SamplerParams::fromIni(sec);
	};
	EXPECT_NO_THROW(load(text));
	EXPECT_THROW(load(text + "seed=3\n"), core::Error);  // unknown key
	std::string swapped = text;
	swapped.replace(swapped.find("r1=0.2"), 6, "r1=0.5");  // r1 > r2
	EXPECT_THROW(load(swapped), core::Error);
	const auto rule = [&](const std::string& value) {
		std::string t = text;
		t.replace(t.find("acceptance=gibbs"), 16, "acceptance=" + value);
		return load(t).acceptance;
	};
	EXPECT_EQ(rule("gibbs"), inference::AcceptanceRule::Gibbs);
	EXPECT_EQ(rule("reversible_jump"), inference::AcceptanceRule::ReversibleJump);
	EXPECT_THROW(rule("metropolis"), core::Error);
	EXPECT_THROW(rule("Gibbs"), core::Error);
	// `proposals` is optional: data-driven unless the broad baseline is asked for by name.
	EXPECT_EQ(load(text).proposals, inference::Proposals::DataDriven);
	EXPECT_EQ(load(text + "proposals=broad\n").proposals, inference::Proposals::Broad);
	EXPECT_EQ(load(text + "proposals=data_driven\n").proposals, inference::Proposals::DataDriven);
	EXPECT_THROW(load(text + "proposals=uniform\n"), core::Error);
}
