// The object catalogue (config/objects.ini, doc/formats.md): strict parsing, one-line errors
// naming the file, the line and the key; the model key `objects` resolved relative to the config.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/ObjectCatalogue.h>

#include "../TempDirTest.h"

#include <fstream>

using namespace whiskermap;
using model::ObjectCatalogue;

namespace
{
class ObjectCatalogueFile : public test::TempDirTest
{
   protected:
	std::string write(const std::string& text)
	{
		const std::string p = path("objects.ini");
		std::ofstream(p) << text;
		return p;
	}
	/** The error of loading `text`, "" if it loads. */
	std::string error(const std::string& text)
	{
		try
		{
			ObjectCatalogue::load(write(text));
		}
		catch (const core::Error& e)
		{
			return e.what();
		}
		return "";
	}
};

const std::string CHAIR = "[chair]\nlength=0.42\nwidth=0.42\nleg_width=0.03\ntexture=0.5\nsize_sigma=0.02\nprior=";
}  // namespace

TEST_F(ObjectCatalogueFile, ShippedCatalogueHoldsTheOfficeClasses)
{
	const auto c = ObjectCatalogue::load(WHISKERMAP_SOURCE_DIR "/config/objects.ini");
	ASSERT_EQ(c.size(), 4u);
	EXPECT_EQ(c[0].name, "table");
	EXPECT_EQ(c[2].name, "chair");
	EXPECT_EQ(c[2].length, 0.42);
	EXPECT_EQ(c[2].leg_width, 0.03);
	EXPECT_EQ(c[3].name, "meeting_table");
	EXPECT_EQ(c[3].label, "table");
	EXPECT_EQ(c[1].label, "desk");
	double sum = 0;
	for (const auto& k : c) sum += k.prior;
	EXPECT_NEAR(sum, 1, 1e-12);
}

TEST_F(ObjectCatalogueFile, OneClassLoads)
{
	const auto c = ObjectCatalogue::load(write(CHAIR + "1\n"));
	ASSERT_EQ(c.size(), 1u);
	EXPECT_EQ(c[0].width, 0.42);
	EXPECT_EQ(c[0].texture, 0.5);
	EXPECT_EQ(c[0].size_sigma, 0.02);
	EXPECT_EQ(c[0].prior, 1);
}

TEST_F(ObjectCatalogueFile, LegSpreadsAreOptionalAndBounded)
{
	// eq. 26's spreads: 0 (the class's legs, fixed) unless given, in [0, 1].
	const auto plain = ObjectCatalogue::load(write(CHAIR + "1\n"));
	EXPECT_EQ(plain[0].leg_width_sigma, 0.0);
	EXPECT_EQ(plain[0].texture_sigma, 0.0);
	const auto spread = ObjectCatalogue::load(write(CHAIR + "1\nleg_width_sigma=0.005\ntexture_sigma=0.1\n"));
	EXPECT_EQ(spread[0].leg_width_sigma, 0.005);
	EXPECT_EQ(spread[0].texture_sigma, 0.1);
	EXPECT_NE(error(CHAIR + "1\nleg_width_sigma=-0.01\n").find("[chair] leg_width_sigma"), std::string::npos);
	EXPECT_NE(error(CHAIR + "1\ntexture_sigma=nan\n").find("[chair] texture_sigma"), std::string::npos);
	EXPECT_NE(error(CHAIR + "1\ntexture_sigma=2\n").find("[chair] texture_sigma"), std::string::npos);
}

TEST_F(ObjectCatalogueFile, UnknownKeyNamesFileLineAndKey)
{
	const std::string e = error(CHAIR + "1\ncolour=3\n");
	EXPECT_NE(e.find("objects.ini: line 8: [chair] colour: unknown key"), std::string::npos) << e;
}

TEST_F(ObjectCatalogueFile, MissingKeyIsAnError)
{
	const std::string e = error("[chair]\nlength=0.42\nwidth=0.42\nleg_width=0.03\ntexture=0.5\nprior=1\n");
	EXPECT_NE(e.find("objects.ini: line 1: [chair] size_sigma: missing required key"), std::string::npos) << e;
}

TEST_F(ObjectCatalogueFile, RepeatedKeyIsAnError)
{
	const std::string e = error(CHAIR + "1\nlength=0.5\n");
	EXPECT_NE(e.find("objects.ini: line 8"), std::string::npos) << e;
	EXPECT_NE(e.find("length"), std::string::npos) << e;
}

TEST_F(ObjectCatalogueFile, RepeatedClassIsAnError)
{
	const std::string e = error(CHAIR + "0.5\n" + CHAIR + "0.5\n");
	EXPECT_NE(e.find("objects.ini: line 8"), std::string::npos) << e;
	EXPECT_NE(e.find("chair"), std::string::npos) << e;
}

TEST_F(ObjectCatalogueFile, NonPositiveSizeIsAnError)
{
	const std::string e = error("[chair]\nlength=0\nwidth=0.42\nleg_width=0.03\ntexture=0.5\nsize_sigma=0.02\nprior=1\n");
	EXPECT_NE(e.find("objects.ini: line 2: [chair] length: "), std::string::npos) << e;
	EXPECT_NE(e.find("out of range"), std::string::npos) << e;
	const std::string w = error("[chair]\nlength=0.42\nwidth=-1\nleg_width=0.03\ntexture=0.5\nsize_sigma=0.02\nprior=1\n");
	EXPECT_NE(w.find("line 3: [chair] width: "), std::string::npos) << w;
}

TEST_F(ObjectCatalogueFile, LegAsWideAsTheObjectIsAnError)
{
	const std::string e = error("[chair]\nlength=0.42\nwidth=0.42\nleg_width=0.5\ntexture=0.5\nsize_sigma=0.02\nprior=1\n");
	EXPECT_NE(e.find("line 4: [chair] leg_width: must be smaller than length and width"), std::string::npos) << e;
}

TEST_F(ObjectCatalogueFile, BadProbabilityIsAnError)
{
	EXPECT_NE(error(CHAIR + "1.5\n").find("line 7: [chair] prior: "), std::string::npos);
	EXPECT_NE(error(CHAIR + "0\n").find("line 7: [chair] prior: "), std::string::npos);
	EXPECT_NE(error(CHAIR + "abc\n").find("line 7: [chair] prior: 'abc' is not a number"), std::string::npos);
	const std::string sum = error(CHAIR + "0.5\n");
	EXPECT_NE(sum.find("line 7: [chair] prior: the classes' priors sum to 0.5"), std::string::npos) << sum;
}

TEST_F(ObjectCatalogueFile, BadNamesAndEmptyFilesAreErrors)
{
	EXPECT_NE(error("[bad-name]\n").find("class name must be"), std::string::npos);
	EXPECT_NE(error(CHAIR + "1\nlabel=no way\n").find("[chair] label: 'no way' is not a class name"), std::string::npos);
	EXPECT_NE(error("; nothing\n").find("objects.ini: no class"), std::string::npos);
	try
	{
		ObjectCatalogue::load(path("missing.ini"));
		ADD_FAILURE() << "a missing catalogue loaded";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("missing.ini"), std::string::npos) << e.what();
	}
}

TEST_F(ObjectCatalogueFile, ModelKeyObjectsIsResolvedRelativeToTheConfig)
{
	write(CHAIR + "1\n");
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("m", "objects", "objects.ini");
	core::IniSection none(cfg, "m", path("map.ini"));
	// only the objects key given: every other model key is then missing
	try
	{
		model::ModelParams::fromIni(none);
		ADD_FAILURE() << "a model section without its required keys loaded";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("missing required key"), std::string::npos) << e.what();
	}
	mrpt::config::CConfigFileMemory full;
	const model::ModelParams d;
	for (const auto& [k, v] : std::vector<std::pair<std::string, double>>{
			 {"sigma_r", d.sigma_r}, {"sigma_theta", d.sigma_theta}, {"sigma_w", d.sigma_w}, {"sigma_tau", d.sigma_tau},
			 {"c_T", d.c_T}, {"c_L", d.c_L}, {"c_S", d.c_S}, {"alpha_L", d.alpha_L}, {"alpha_S", d.alpha_S},
			 {"epsilon", d.epsilon}, {"delta", d.delta}, {"table_length", d.table_length},
			 {"table_width", d.table_width}, {"leg_width", d.leg_width}, {"texture", d.texture},
			 {"parent_gate", d.parent_gate}})
		full.write("m", k, v);
	core::IniSection without(full, "m", path("map.ini"));
	EXPECT_TRUE(model::ModelParams::fromIni(without).classes.empty());
	full.write("m", "objects", "objects.ini");
	core::IniSection with(full, "m", path("map.ini"));
	const model::ModelParams p = model::ModelParams::fromIni(with);
	ASSERT_EQ(p.classCount(), 1);
	EXPECT_EQ(p.lengthOf(0), 0.42);
	EXPECT_EQ(p.nameOf(0), "chair");
	full.write("m", "objects", "nowhere.ini");
	core::IniSection bad(full, "m", path("map.ini"));
	EXPECT_THROW(model::ModelParams::fromIni(bad), core::Error);
}
