#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/ModelParams.h>

using namespace whiskermap;
using model::ModelParams;

namespace
{
ModelParams shipped()
{
	mrpt::config::CConfigFile cfg(WHISKERMAP_SOURCE_DIR "/config/whisker-map.ini");
	core::IniSection sec(cfg, "MetricMap_hierarchicalObjectMap_00_model", "whisker-map.ini");
	return ModelParams::fromIni(sec);
}
}  // namespace

TEST(ModelParams, ShippedConfigEqualsBuiltInDefaults)
{
	const ModelParams f = shipped(), d;
	EXPECT_EQ(f.sigma_r, d.sigma_r);
	EXPECT_EQ(f.sigma_theta, d.sigma_theta);
	EXPECT_EQ(f.sigma_w, d.sigma_w);
	EXPECT_EQ(f.sigma_tau, d.sigma_tau);
	EXPECT_EQ(f.shaft_noise, d.shaft_noise);
	EXPECT_EQ(f.sigma_across, d.sigma_across);
	EXPECT_EQ(f.sigma_corner, d.sigma_corner);
	EXPECT_EQ(f.c_T, d.c_T);
	EXPECT_EQ(f.c_L, d.c_L);
	EXPECT_EQ(f.c_S, d.c_S);
	EXPECT_EQ(f.alpha_L, d.alpha_L);
	EXPECT_EQ(f.alpha_S, d.alpha_S);
	EXPECT_EQ(f.epsilon, d.epsilon);
	EXPECT_EQ(f.delta, d.delta);
	EXPECT_EQ(f.table_length, d.table_length);
	EXPECT_EQ(f.table_width, d.table_width);
	EXPECT_EQ(f.leg_width, d.leg_width);
	EXPECT_EQ(f.texture, d.texture);
	EXPECT_EQ(f.parent_gate, d.parent_gate);
	EXPECT_EQ(f.free_space, d.free_space);
	EXPECT_EQ(f.free_space_p_miss, d.free_space_p_miss);
	EXPECT_TRUE(f == d);
}

// eq. 10: uncaused, small things are less likely than large ones: p(S) < p(L) < p(T).
TEST(ModelParams, DefaultsKeepEq10)
{
	const ModelParams p = shipped();
	EXPECT_LT(model::logShapeletNull(p), model::logLegNull(p));
	EXPECT_LT(model::logLegNull(p), model::logTablePrior(p));
}

TEST(ModelParams, UnknownMissingAndBadKeysFail)
{
	std::string text = "[model]\n";
	for (const char* kv :
		 {"sigma_r=0.01", "sigma_theta=0.1", "sigma_w=0.01", "sigma_tau=0.1", "c_T=0.01", "c_L=0.001",
		  "c_S=0.0001", "alpha_L=1", "alpha_S=1", "epsilon=0.01", "delta=0.01", "table_length=1",
		  "table_width=0.6", "leg_width=0.05", "texture=0.5", "parent_gate=0.05"})
		text += std::string(kv) + "\n";
	const auto load = [](const std::string& t) {
		mrpt::config::CConfigFileMemory cfg(t);
		core::IniSection sec(cfg, "model", "test.ini");
		return ModelParams::fromIni(sec);
	};
	EXPECT_EQ(load(text).table_width, 0.6);
	EXPECT_THROW(load(text + "sigma_rr=1\n"), core::Error);  // misspelt extra key
	const auto with = [&](const std::string& from, const std::string& to) {
		std::string t = text;
		return t.replace(t.find(from), from.size(), to);
	};
	EXPECT_THROW(load(with("epsilon=0.01", "epsilon=2")), core::Error);  // out of range
	EXPECT_THROW(load(with("delta=0.01\n", "")), core::Error);  // missing
	EXPECT_THROW(load(with("leg_width=0.05", "leg_width=0.7")), core::Error);  // wider than the table
	// Shaft noise: optional (the paper's eq. 7 without), strict when given.
	EXPECT_FALSE(load(text).shaft_noise);
	EXPECT_TRUE(load(text + "shaft_noise=true\nsigma_across=0.003\n").shaft_noise);
	EXPECT_EQ(load(text + "sigma_across=0.003\n").sigma_across, 0.003);
	EXPECT_THROW(load(text + "shaft_noise=maybe\n"), core::Error);
	EXPECT_THROW(load(text + "sigma_across=0\n"), core::Error);
	// sigma_corner (eq. 6) is optional: sigma_r when absent, strict when given.
	EXPECT_EQ(load(with("sigma_r=0.01", "sigma_r=0.03")).sigma_corner, 0.03);
	EXPECT_EQ(load(text + "sigma_corner=0.002\n").sigma_corner, 0.002);
	EXPECT_THROW(load(text + "sigma_corner=0\n"), core::Error);
	EXPECT_THROW(load(text + "sigma_corner=nan\n"), core::Error);
	// The free-space keys are optional (eq. 21: off, p_miss 0.05), read strictly when given.
	EXPECT_FALSE(load(text).free_space);
	EXPECT_EQ(load(text).free_space_p_miss, 0.05);
	const ModelParams on = load(text + "free_space=true\nfree_space_p_miss=0.2\n");
	EXPECT_TRUE(on.free_space);
	EXPECT_EQ(on.free_space_p_miss, 0.2);
	EXPECT_FALSE(on == load(text));
	EXPECT_THROW(load(text + "free_space=maybe\n"), core::Error);
	EXPECT_THROW(load(text + "free_space_p_miss=0\n"), core::Error);  // out of range
	EXPECT_THROW(load(text + "free_space_p_miss=1.5\n"), core::Error);
	EXPECT_THROW(load(text + "free_spaces=true\n"), core::Error);  // misspelt
}
