#include <whiskermap/core/Error.h>
#include <mrpt/config/CConfigFile.h>
#include <whiskermap/core/IniSection.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <vector>

namespace whiskermap::core
{
namespace
{
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r\n");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t\r\n");
	return s.substr(b, e - b + 1);
}
std::string stripComment(const std::string& s)
{
	const auto c = s.find_first_of(";#");
	return trim(c == std::string::npos ? s : s.substr(0, c));
}
std::string lower(std::string s)
{
	std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
	return s;
}
}  // namespace

IniSection::IniSection(
	const mrpt::config::CConfigFileBase& cfg, std::string section, std::string fileLabel)
	: m_cfg(cfg), m_section(std::move(section)), m_file(std::move(fileLabel))
{
}

bool IniSection::has(const std::string& key) const { return m_cfg.keyExists(m_section, key); }

void IniSection::fail(const std::string& key, const std::string& problem) const
{
	std::string where = iniWhere(m_cfg, m_section, key, m_file) + "[" + m_section + "]";
	if (!key.empty()) where += " " + key;
	throw Error(where + ": " + problem);
}

std::string IniSection::raw(const std::string& key)
{
	if (!has(key)) fail(key, "missing required key");
	m_read.insert(key);
	return stripComment(m_cfg.read_string(m_section, key, ""));
}

double IniSection::parseNumber(const std::string& key, const std::string& s) const
{
	size_t used = 0;
	double v = 0;
	try
	{
		v = std::stod(s, &used);
	}
	catch (const std::exception&)
	{
		fail(key, "'" + s + "' is not a number");
	}
	if (used != s.size()) fail(key, "'" + s + "' is not a number");
	if (!std::isfinite(v)) fail(key, "'" + s + "' is not finite");
	return v;
}

double IniSection::number(const std::string& key, double lo, double hi)
{
	const std::string s = raw(key);
	const double v = parseNumber(key, s);
	if (v < lo || v > hi)
	{
		const auto shortest = [](double x) {  // as a user writes it: 0.001, 1000, 1e+06
			std::ostringstream o;
			o << std::setprecision(15) << x;
			return o.str();
		};
		fail(key, "'" + s + "' out of range [" + shortest(lo) + ", " + shortest(hi) + "]");
	}
	return v;
}

double IniSection::number(const std::string& key, double def, double lo, double hi)
{
	return has(key) ? number(key, lo, hi) : def;
}

long IniSection::integer(const std::string& key, long lo, long hi)
{
	const double v = number(key, static_cast<double>(lo), static_cast<double>(hi));
	if (v != std::floor(v)) fail(key, "expected a whole number");
	return static_cast<long>(v);
}

long IniSection::integer(const std::string& key, long def, long lo, long hi)
{
	return has(key) ? integer(key, lo, hi) : def;
}

bool IniSection::boolean(const std::string& key, bool def)
{
	if (!has(key)) return def;
	const std::string s = lower(raw(key));
	if (s == "true" || s == "1" || s == "yes") return true;
	if (s == "false" || s == "0" || s == "no") return false;
	fail(key, "'" + s + "' is not a boolean (true/false)");
}

std::string IniSection::text(const std::string& key, const std::string& def)
{
	return has(key) ? raw(key) : def;
}

void IniSection::finish() const
{
	std::vector<std::string> keys;
	m_cfg.getAllKeys(m_section, keys);
	for (const auto& k : keys)
		if (!m_read.count(k)) fail(k, "unknown key");
}

std::unique_ptr<IniFile> openIniFile(const std::string& path, const std::string& kind)
{
	std::error_code ec;
	if (!std::filesystem::is_regular_file(path, ec)) throw Error(path + ": no such " + kind);
	if (std::filesystem::file_size(path, ec) > IniFile::MAX_BYTES) throw Error(path + ": larger than 64 MiB, not a " + kind);
	std::ifstream f(path, std::ios::binary);
	std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	if (f.bad()) throw Error(path + ": cannot read " + kind);
	return std::make_unique<IniFile>(text, path);
}

std::string configLabel(const mrpt::config::CConfigFileBase& cfg)
{
	if (const auto* ini = dynamic_cast<const IniFile*>(&cfg)) return ini->label();
	const auto* file = dynamic_cast<const mrpt::config::CConfigFile*>(&cfg);
	return file && !file->getAssociatedFile().empty() ? file->getAssociatedFile() : "<config>";
}

std::string iniWhere(
	const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key,
	const std::string& label)
{
	const auto* ini = dynamic_cast<const IniFile*>(&cfg);
	int line = ini ? ini->lineOf(section, key) : 0;
	if (ini && !line) line = ini->lineOf(section);
	return (label.empty() ? configLabel(cfg) : label) + ": " + (line ? "line " + std::to_string(line) + ": " : "");
}

long sectionIndex(const std::string& section, const std::string& prefix, long limit)
{
	if (section.rfind(prefix, 0) != 0) return -1;
	const std::string n = section.substr(prefix.size());
	if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos) return -1;
	if (n.size() > 1 && n[0] == '0') return -1;
	const long v = std::stol(n);
	return v < limit ? v : -1;
}

void rejectUnknownSections(
	const mrpt::config::CConfigFileBase& cfg, const std::set<std::string>& allowed,
	const std::string& prefix, const std::string& fileLabel)
{
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& s : sections)
	{
		if (s.empty() || allowed.count(s)) continue;
		if (!prefix.empty() && s.rfind(prefix, 0) == 0) continue;
		throw Error(iniWhere(cfg, s, "", fileLabel) + "[" + s + "]: unknown section");
	}
}
}  // namespace whiskermap::core
