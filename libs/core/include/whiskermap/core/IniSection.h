#pragma once
#include <mrpt/config/CConfigFileBase.h>
#include <whiskermap/core/IniFile.h>

#include <memory>

#include <set>
#include <string>

namespace whiskermap::core
{
/** Strict, typed reader of one section of an MRPT-style .ini file.
 *
 * Every getter checks the value parses completely (a trailing `; comment` is allowed) and is
 * finite; range-checked getters also check bounds. `finish()` then rejects any key in the
 * section that no getter asked for, so a misspelt key is an error, never silently ignored.
 * All errors are core::Error with a one-line message "FILE: line N: [SECTION] KEY: problem". */
class IniSection
{
   public:
	IniSection(const mrpt::config::CConfigFileBase& cfg, std::string section, std::string fileLabel);

	bool has(const std::string& key) const;
	/** Required number in [lo, hi]. */
	double number(const std::string& key, double lo, double hi);
	/** Optional number in [lo, hi], `def` when absent. */
	double number(const std::string& key, double def, double lo, double hi);
	/** Required integer in [lo, hi]. */
	long integer(const std::string& key, long lo, long hi);
	/** Optional integer in [lo, hi], `def` when absent. */
	long integer(const std::string& key, long def, long lo, long hi);
	/** Optional boolean (true/false/1/0/yes/no). */
	bool boolean(const std::string& key, bool def);
	/** Optional string, `def` when absent. */
	std::string text(const std::string& key, const std::string& def);

	/** Throws if the section holds keys that were never read. */
	void finish() const;

	/** Throws an error naming this file and section (and key, if not empty). */
	[[noreturn]] void fail(const std::string& key, const std::string& problem) const;

	const std::string& section() const { return m_section; }
	const std::string& fileLabel() const { return m_file; }

   private:
	std::string raw(const std::string& key);  // value without comment; throws if missing
	double parseNumber(const std::string& key, const std::string& s) const;

	const mrpt::config::CConfigFileBase& m_cfg;
	std::string m_section, m_file;
	std::set<std::string> m_read;
};

/** Reads an .ini file strictly (IniFile: bounded size, no duplicates, no control bytes, no
 *  preprocessor syntax, ...). `kind` names the file in errors ("world file" -> "x.ini: no
 *  such world file", "x.ini: line 3: malformed line '...'"). */
std::unique_ptr<IniFile> openIniFile(const std::string& path, const std::string& kind);

/** Error-message prefix "FILE: line N: " for a section (and key) when `cfg` is an IniFile
 *  that has it, else "FILE: ". FILE is `label`, or configLabel(cfg) when empty. */
std::string iniWhere(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key = "",
	const std::string& label = "");

/** The file behind a config source (its path for a CConfigFile), for error messages. */
std::string configLabel(const mrpt::config::CConfigFileBase& cfg);

/** The index N of a section named `prefix` + N, N written without leading zeros and below
 *  `limit`; -1 when the name is not of that form (so [table_01] and [table_1] cannot both
 *  name table 1). */
long sectionIndex(const std::string& section, const std::string& prefix, long limit);

/** Throws if `cfg` has a section not in `allowed` (exact names), or, when `prefix` is not
 *  empty, not starting with it. Used to reject unknown sections in strict files; the error
 *  names the file and the section's line. */
void rejectUnknownSections(
	const mrpt::config::CConfigFileBase& cfg, const std::set<std::string>& allowed,
	const std::string& prefix, const std::string& fileLabel);
}  // namespace whiskermap::core
