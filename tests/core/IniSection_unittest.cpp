#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>

using whiskermap::core::Error;
using whiskermap::core::IniSection;

namespace
{
mrpt::config::CConfigFileMemory ini(const std::string& text)
{
	return mrpt::config::CConfigFileMemory(text);
}
std::string errorOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const Error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(IniSection, ReadsNumbersWithTrailingComments)
{
	auto cfg = ini("[s]\na=1.5   ; metres\nb = -2 # note\nn=7\n");
	IniSection s(cfg, "s", "f.ini");
	EXPECT_DOUBLE_EQ(s.number("a", 0, 10), 1.5);
	EXPECT_DOUBLE_EQ(s.number("b", -5, 5), -2);
	EXPECT_EQ(s.integer("n", 0, 10), 7);
	EXPECT_DOUBLE_EQ(s.number("absent", 3.0, 0, 10), 3.0);
	EXPECT_NO_THROW(s.finish());
}

TEST(IniSection, RejectsUnknownKeyNamingFileSectionKey)
{
	auto cfg = ini("[s]\na=1\ntypo=2\n");
	IniSection s(cfg, "s", "f.ini");
	s.number("a", 0, 10);
	EXPECT_EQ(errorOf([&] { s.finish(); }), "f.ini: [s] typo: unknown key");
}

TEST(IniSection, RejectsMissingBadAndOutOfRangeValues)
{
	auto cfg = ini("[s]\nword=abc\nhalf=1.5x\nbig=100\nnan=nan\nfrac=2.5\nflag=maybe\n");
	IniSection s(cfg, "s", "f.ini");
	EXPECT_EQ(errorOf([&] { s.number("missing", 0, 1); }), "f.ini: [s] missing: missing required key");
	EXPECT_EQ(errorOf([&] { s.number("word", 0, 1); }), "f.ini: [s] word: 'abc' is not a number");
	EXPECT_EQ(errorOf([&] { s.number("half", 0, 1); }), "f.ini: [s] half: '1.5x' is not a number");
	EXPECT_EQ(errorOf([&] { s.number("big", 0, 10); }), "f.ini: [s] big: '100' out of range [0, 10]");
	EXPECT_EQ(errorOf([&] { s.number("big", 0.001, 99.5); }), "f.ini: [s] big: '100' out of range [0.001, 99.5]");
	EXPECT_NE(errorOf([&] { s.number("nan", 0, 10); }).find("not finite"), std::string::npos);
	EXPECT_NE(errorOf([&] { s.integer("frac", 0, 10); }).find("whole number"), std::string::npos);
	EXPECT_NE(errorOf([&] { s.boolean("flag", true); }).find("not a boolean"), std::string::npos);
}

TEST(IniSection, RejectsUnknownSections)
{
	auto cfg = ini("[arena]\nx=1\n[table_0]\nx=1\n[tabel_1]\nx=2\n");
	EXPECT_EQ(
		errorOf([&] { whiskermap::core::rejectUnknownSections(cfg, {"arena"}, "table_", "w.ini"); }),
		"w.ini: [tabel_1]: unknown section");
}
