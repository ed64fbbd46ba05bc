#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniFile.h>

#include <algorithm>
#include <cctype>

namespace whiskermap::core
{
namespace
{
std::string lower(std::string s)
{
	std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
	return s;
}
std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r");
	if (b == std::string::npos) return {};
	return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
bool isName(const std::string& s)
{
	return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) {
		return std::isalnum(c) || c == '_' || c == '.' || c == '-';
	});
}
}  // namespace

IniFile::IniFile(const std::string& text, std::string label) : m_label(std::move(label))
{
	setContent(parse(text, m_label, m_lines, m_order));
}

std::string IniFile::parse(
	const std::string& text, const std::string& label, std::map<std::string, int>& lines, std::vector<std::string>& order)
{
	if (text.size() > MAX_BYTES) throw Error(label + ": larger than 64 MiB, not a config file");
	std::string clean, section;
	size_t start = 0;
	for (int n = 1; start < text.size(); n++)
	{
		const size_t end = std::min(text.find('\n', start), text.size());
		const std::string where = label + ": line " + std::to_string(n) + ": ";
		if (end - start > MAX_LINE) throw Error(where + "longer than 4096 bytes");
		std::string line = text.substr(start, end - start);
		start = end + 1;
		for (const unsigned char c : line)
			if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f)
				throw Error(where + "holds a control byte " + std::to_string(int(c)) + (c ? "" : " (NUL)"));
		const std::string t = trim(line.substr(0, line.find_first_of(";#")));
		if (t.empty()) continue;
		const std::string raw = trim(line);
		if (raw[0] == '@') throw Error(where + "MRPT config directives (@define, @include) are not supported");
		for (const char* x : {"${", "$eval{", "$env{", "<<<"})
			if (t.find(x) != std::string::npos)
				throw Error(where + "'" + x + "' (MRPT config preprocessor syntax) is not supported: give plain values");
		if (t.front() == '[')
		{
			if (t.back() != ']' || !isName(t.substr(1, t.size() - 2)))
				throw Error(where + "malformed section header (expected [name], name of letters, digits, _ . -)");
			section = t.substr(1, t.size() - 2);
			if (!lines.emplace(lower(section), n).second)
				throw Error(where + "[" + section + "] appears twice (first on line " +
							std::to_string(lines[lower(section)]) + ")");
			order.push_back(section);
			clean += "[" + section + "]\n";
			continue;
		}
		const auto eq = t.find('=');
		if (eq == std::string::npos) throw Error(where + "malformed line '" + t + "' (expected key = value)");
		const std::string key = trim(t.substr(0, eq)), value = trim(t.substr(eq + 1));
		if (!isName(key)) throw Error(where + "malformed key '" + key + "' (letters, digits, _ . -)");
		if (section.empty()) throw Error(where + "key '" + key + "' outside any [section]");
		const auto [it, fresh] = lines.emplace(lower(section) + "\n" + lower(key), n);
		if (!fresh)
			throw Error(where + "[" + section + "] " + key + " is given twice (first on line " + std::to_string(it->second) + ")");
		clean += key + "=" + value + "\n";
	}
	return clean;
}

int IniFile::lineOf(const std::string& section, const std::string& key) const
{
	const auto it = m_lines.find(lower(section) + (key.empty() ? "" : "\n" + lower(key)));
	return it == m_lines.end() ? 0 : it->second;
}
}  // namespace whiskermap::core
