#include <whiskermap/core/Error.h>
#include <whiskermap/core/LineReader.h>

#include <filesystem>

namespace whiskermap::core
{
LineReader::LineReader(const std::string& path, const std::string& kind, size_t maxLine)
	: m_path(path), m_max(maxLine)
{
	std::error_code ec;
	if (!std::filesystem::is_regular_file(path, ec)) throw Error(path + ": no such " + kind);
	m_in.open(path, std::ios::binary);
	if (!m_in) throw Error(path + ": cannot read " + kind);
}

std::string LineReader::where() const { return m_path + ": line " + std::to_string(m_line) + ": "; }

bool LineReader::next(std::string& line)
{
	line.clear();
	int c = 0;
	bool any = false;
	while ((c = m_in.get()) != std::char_traits<char>::eof())
	{
		any = true;
		if (c == '\n') break;
		if (line.size() == m_max)
		{
			m_line++;
			throw Error(where() + "longer than " + std::to_string(m_max) + " bytes");
		}
		line.push_back(static_cast<char>(c));
	}
	if (m_in.bad()) throw Error(m_path + ": read error");
	if (!any) return false;
	m_line++;
	if (!line.empty() && line.back() == '\r') line.pop_back();
	for (const unsigned char b : line)
		if ((b < 0x20 && b != '\t') || b == 0x7f)
			throw Error(where() + "holds a control byte " + std::to_string(int(b)) + (b ? "" : " (NUL)"));
	return true;
}
}  // namespace whiskermap::core
