#pragma once
#include <mrpt/config/CConfigFileMemory.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace whiskermap::core
{
/** An .ini file read strictly (doc/formats.md, "Strict .ini files"), then handed to MRPT as
 *  a CConfigFileMemory of its clean content (comments removed), so MRPT's own loaders read
 *  exactly what was checked. Refused, each with "FILE: line N: problem": a file over 64 MiB
 *  or a line over 4096 bytes, a NUL or other control byte, a line that is not blank, a
 *  comment (; or #), a [section] or a key = value, a key before any section, a section or
 *  key given twice (names compare case-insensitively, as MRPT does), and MRPT's config
 *  preprocessor syntax ($eval{...}, ${VAR}, $env{VAR}, @define, @include, <<<): whiskermap
 *  files use plain values, and MRPT would expand these even inside comments. */
class IniFile : public mrpt::config::CConfigFileMemory
{
   public:
	static constexpr size_t MAX_BYTES = 64u << 20, MAX_LINE = 4096;

	/** Parses `text`; `label` (the file name) starts every error message. */
	IniFile(const std::string& text, std::string label);

	const std::string& label() const { return m_label; }
	/** Line of a section header, or of a key in it; 0 when absent. */
	int lineOf(const std::string& section, const std::string& key = "") const;
	/** Sections in file order, as written. */
	const std::vector<std::string>& sectionsInOrder() const { return m_order; }

   private:
	static std::string parse(const std::string& text, const std::string& label, std::map<std::string, int>& lines,
							 std::vector<std::string>& order);
	std::string m_label;
	std::map<std::string, int> m_lines;  ///< "section" and "section\nkey", lower case -> line
	std::vector<std::string> m_order;
};
}  // namespace whiskermap::core
