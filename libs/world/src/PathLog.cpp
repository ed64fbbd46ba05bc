#include <whiskermap/core/Error.h>
#include <whiskermap/world/PathLog.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace whiskermap::world
{
std::vector<PathLog::Entry> PathLog::read(const std::string& path)
{
	Reader r(path);
	std::vector<Entry> out;
	for (Entry e; r.next(e);) out.push_back(e);
	return out;
}

size_t PathLog::count(const std::string& path, size_t limit)
{
	Reader r(path);
	for (Entry e; r.count() < limit && r.next(e);)
	{
	}
	return r.count();
}

PathLog::Reader::Reader(const std::string& path) : m_path(path), m_in(path, "file") {}

bool PathLog::Reader::next(Entry& e)
{
	for (std::string text; m_in.next(text);)
	{
		const auto b = text.find_first_not_of(" \t");
		if (b == std::string::npos || text[b] == '%' || text[b] == '#') continue;
		const std::string where = m_in.where();
		std::istringstream s(text);
		double t, x, y, yaw;
		std::string extra;
		if (!(s >> t >> x >> y >> yaw) || (s >> extra))
			throw core::Error(where + "expected 'timestamp x y yaw', got '" + text + "'");
		if (!std::isfinite(t) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(yaw))
			throw core::Error(where + "a value is not finite in '" + text + "'");
		if (m_count > 0 && t < m_lastT)
			throw core::Error(where + "timestamp " + std::to_string(t) + " goes backwards");
		e = {t, {x, y, yaw}, static_cast<int>(m_in.lineNo())};
		m_lastT = t, m_count++;
		return true;
	}
	if (m_count == 0) throw core::Error(m_path + ": path file holds no poses");
	return false;
}

std::string PathLog::header(const std::string& title)
{
	return "% " + title + "\n% timestamp(s)  x(m)  y(m)  yaw(rad)\n";
}

std::string PathLog::line(double t, const mrpt::poses::CPose2D& p)
{
	char buf[160];
	std::snprintf(buf, sizeof(buf), "%.6f %.9f %.9f %.9f\n", t, p.x(), p.y(), p.phi());
	return buf;
}

PathLog::Writer::Writer(const std::string& path, const std::string& title) : m_path(path)
{
	m_out.open(m_path + ".tmp");
	if (!m_out) throw core::Error(m_path + ": cannot create file");
	m_out << header(title);
}

PathLog::Writer::~Writer()
{
	if (m_closed) return;
	m_out.close();
	std::error_code ec;
	std::filesystem::remove(m_path + ".tmp", ec);
}

void PathLog::Writer::write(double t, const mrpt::poses::CPose2D& pose) { m_out << line(t, pose); }

void PathLog::Writer::close()
{
	m_out.close();
	if (!m_out) throw core::Error(m_path + ": write failed");
	std::filesystem::rename(m_path + ".tmp", m_path);
	m_closed = true;
}
}  // namespace whiskermap::world
