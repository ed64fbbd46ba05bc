// Regression tests of issue 8: .ini input MRPT accepted silently or mangled.
#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniFile.h>

using whiskermap::core::IniFile;

namespace
{
/** The error parsing `text`, or "" when it parses. */
std::string error(const std::string& text)
{
	try
	{
		IniFile f(text, "f.ini");
	}
	catch (const whiskermap::core::Error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(IniFile, ReadsPlainFilesAndKnowsLines)
{
	const IniFile f("; comment ${X} $eval{1} $env{HOME}\n[a]\nx = 1 ; trailing\n\n[b]\ny=two words\n", "f.ini");
	EXPECT_EQ(f.read_string("a", "x", ""), "1");
	EXPECT_EQ(f.read_string("b", "y", ""), "two words");
	EXPECT_EQ(f.lineOf("a"), 2);
	EXPECT_EQ(f.lineOf("b", "y"), 6);
	EXPECT_EQ(f.sectionsInOrder(), (std::vector<std::string>{"a", "b"}));
}

TEST(IniFile, DuplicatesAreErrorsNamingBothLines)  // the last one silently won
{
	EXPECT_EQ(error("[a]\nx=1\n[b]\n[a]\n"), "f.ini: line 4: [a] appears twice (first on line 1)");
	EXPECT_EQ(error("[a]\nx=1\nX=2\n"), "f.ini: line 3: [a] X is given twice (first on line 2)");
	EXPECT_EQ(error("[Sec]\n[sec]\n"), "f.ini: line 2: [sec] appears twice (first on line 1)");
}

TEST(IniFile, KeysOutsideSectionsAreErrors)  // were ignored
{
	EXPECT_EQ(error("x=1\n[a]\n"), "f.ini: line 1: key 'x' outside any [section]");
}

TEST(IniFile, NulAndControlBytesAreErrors)  // a NUL dropped the rest of the file
{
	EXPECT_EQ(error(std::string("[a]\nx=1\0\ny=2\n", 13)), "f.ini: line 2: holds a control byte 0 (NUL)");
	EXPECT_NE(error("[a]\nx=\x1b[31m\n").find("line 2: holds a control byte 27"), std::string::npos);
}

TEST(IniFile, MrptPreprocessorSyntaxIsAClearErrorOutsideComments)  // printed "==== MRPT exception ===="
{
	EXPECT_NE(error("[a]\nx=$eval{1+1}\n").find("line 2: '$eval{' (MRPT config preprocessor syntax) is not supported"),
			  std::string::npos);
	EXPECT_NE(error("[a]\nx=${V}\n").find("line 2: '${'"), std::string::npos);
	EXPECT_NE(error("[a]\nx=$env{HOME}\n").find("line 2: '$env{'"), std::string::npos);
	EXPECT_NE(error("@define V 1\n[a]\n").find("line 1: MRPT config directives"), std::string::npos);
	EXPECT_NE(error("[a]\nx=<<<END\n").find("'<<<'"), std::string::npos);
}

TEST(IniFile, MalformedLinesAndNamesAreErrors)
{
	EXPECT_NE(error("[a b]\n").find("line 1: malformed section header"), std::string::npos);
	EXPECT_NE(error("[a]]\n").find("line 1: malformed section header"), std::string::npos);
	EXPECT_NE(error("[a]\njust words\n").find("line 2: malformed line"), std::string::npos);
	EXPECT_NE(error("[a]\nx y=1\n").find("line 2: malformed key"), std::string::npos);
	EXPECT_NE(error("[a]\n" + std::string(5000, 'x') + "=1\n").find("line 2: longer than 4096 bytes"), std::string::npos);
	EXPECT_NE(error("[a\rb]\n").find("line 1: malformed section header"), std::string::npos);
}
