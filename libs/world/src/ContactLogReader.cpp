#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/ContactLogReader.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>

namespace whiskermap::world
{
namespace
{
constexpr size_t MAX_LINE = 1 << 16;
constexpr double ANGLE_TOL = 1e-9;	// radians, as CObservationWhiskerContacts::validate

std::string_view trim(std::string_view s)
{
	while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
	while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
		s.remove_suffix(1);
	return s;
}

/** A value for a message: quoted, at most 40 characters, printable. */
std::string quote(std::string_view s)
{
	std::string q(s.substr(0, 40));
	for (char& c : q)
		if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
	return "'" + q + (s.size() > 40 ? "...'" : "'");
}

std::string num(double v)
{
	char b[32];
	std::snprintf(b, sizeof(b), "%g", v);
	return b;
}
std::string deg(double radians) { return num(core::rad2deg(radians)); }
}  // namespace

ContactLogReader::ContactLogReader(
	const std::string& path, const Robot& robot, const obs::TSensorNoise& noise)
	: m_path(path), m_robot(robot), m_noise(noise), m_buffer(MAX_LINE)
{
	namespace fs = std::filesystem;
	if (!fs::exists(path)) throw core::Error(path + ": no such file");
	if (fs::is_directory(path)) throw core::Error(path + ": is a directory, not a contact log");
	m_in.open(path, std::ios::binary);
	if (!m_in) throw core::Error(path + ": cannot open file");
	readFirstLines();
}

bool ContactLogReader::rawLine()
{
	m_in.getline(m_buffer.data(), std::streamsize(m_buffer.size()));
	const auto got = size_t(m_in.gcount());
	if (m_in.bad()) failAt(m_line + 1, "column 1", "read error");
	if (m_in.fail())
	{
		if (m_in.eof() && got == 0) return false;
		failAt(
			m_line + 1, "column 1",
			"line longer than " + std::to_string(MAX_LINE - 1) + " characters");
	}
	m_line++;
	m_text = std::string_view(m_buffer.data(), m_in.eof() ? got : got - 1);
	return true;
}

bool ContactLogReader::dataLine()
{
	while (rawLine())
	{
		const auto t = trim(m_text);
		if (!t.empty() && t.front() != '#') return true;
	}
	return false;
}

void ContactLogReader::readFirstLines()
{
	const std::string_view want = ContactLogFormat::FIRST_LINE;
	const std::string_view prefix = want.substr(0, want.rfind('v') + 1);
	if (!rawLine()) failAt(1, "column 1", "empty file, not a contact log");
	auto first = trim(m_text);
	if (first.substr(0, 3) == "\xEF\xBB\xBF") first.remove_prefix(3);  // a UTF-8 byte-order mark
	if (first != want)
	{
		if (first.substr(0, prefix.size()) == prefix)
			failAt(
				1, "column 1",
				"unsupported format version " + quote(first.substr(prefix.size() - 1)) +
					" (this build reads v1)");
		failAt(
			1, "column 1", "not a contact log: the first line must be '" + std::string(want) + "'");
	}
	if (!dataLine()) failAt(m_line + 1, "column 1", "no header row after the first line");
	m_headerLine = m_line;
	splitFields();
	const auto& names = ContactLogFormat::COLUMNS;
	m_fieldOf.fill(SIZE_MAX);
	for (size_t k = 0; k < m_fields.size(); k++)
	{
		const std::string_view name = m_fields[k];
		const std::string where = "field " + std::to_string(k + 1);
		const auto it = std::find(names.begin(), names.end(), name);
		if (name.empty()) failAt(m_line, where, "empty column name in the header row");
		if (it == names.end())
		{
			std::string known;
			for (auto n : names) known += (known.empty() ? "" : ", ") + std::string(n);
			failAt(m_line, where, "unknown column " + quote(name) + " (columns: " + known + ")");
		}
		auto& slot = m_fieldOf[size_t(it - names.begin())];
		if (slot != SIZE_MAX)
			failAt(
				m_line, where,
				"column " + quote(name) + " repeats field " + std::to_string(slot + 1));
		slot = k;
		m_header.emplace_back(name);
	}
	for (size_t c = 0; c < names.size(); c++)
		if (m_fieldOf[c] == SIZE_MAX)
			failAt(m_line, "column '" + std::string(names[c]) + "'", "missing from the header row");
}

void ContactLogReader::splitFields()
{
	m_fields.clear();
	std::string_view rest = m_text;
	for (;;)
	{
		const size_t comma = rest.find(',');
		m_fields.push_back(trim(rest.substr(0, comma)));
		if (comma == std::string_view::npos) break;
		rest.remove_prefix(comma + 1);
	}
}

void ContactLogReader::fail(Column c, const std::string& problem) const
{
	failAt(
		m_line,
		"column '" + std::string(ContactLogFormat::COLUMNS[c]) + "' (field " +
			std::to_string(m_fieldOf[c] + 1) + ")",
		problem);
}

void ContactLogReader::failAt(
	size_t line, const std::string& where, const std::string& problem) const
{
	throw core::Error(m_path + ": line " + std::to_string(line) + ", " + where + ": " + problem);
}

double ContactLogReader::number(Column c) const
{
	double v = 0;
	if (const char* why = ContactLogFormat::parseNumber(field(c), v))
		fail(c, quote(field(c)) + " " + why);
	return v;
}

double ContactLogReader::degrees(Column c) const
{
	double v = 0;
	if (const char* why = ContactLogFormat::parseDegrees(field(c), v))
		fail(c, quote(field(c)) + " " + why);
	return v;
}

bool ContactLogReader::next(Sweep& out)
{
	const size_t n = m_robot.whiskers.size();
	while (dataLine())
	{
		readRow();
		if (m_sweep.count < n) continue;
		try
		{
			m_sweep.obs->validate();  // the checks above make this pass; belt and braces
		}
		catch (const core::Error& e)
		{
			failAt(m_sweep.line, "column 'whisker'", e.what());
		}
		out = Sweep{
			mrpt::poses::CPose2D(m_sweep.x, m_sweep.y, m_sweep.yaw), m_sweep.obs, m_sweep.line};
		m_lastTime = m_sweep.time;
		m_lastLine = m_sweep.line;
		m_sweep.count = 0;
		m_sweeps++;
		return true;
	}
	if (m_sweep.count > 0)
		failAt(
			m_sweep.line, "column 'whisker'",
			"the file ends before this sweep lists whiskers " + missingWhiskers() +
				" (one row per whisker of the robot)");
	if (m_sweeps == 0)
		failAt(m_headerLine, "column 1", "no data rows after the header row: nothing to import");
	return false;
}

void ContactLogReader::readRow()
{
	splitFields();
	const size_t h = m_header.size();
	if (m_fields.size() < h)
		failAt(
			m_line,
			"column '" + m_header[m_fields.size()] + "' (field " +
				std::to_string(m_fields.size() + 1) + ")",
			"missing value: the row has " + std::to_string(m_fields.size()) +
				" fields, the header " + std::to_string(h));
	if (m_fields.size() > h)
		failAt(
			m_line, "field " + std::to_string(h + 1),
			"extra value " + quote(m_fields[h]) + ": the header has " + std::to_string(h) +
				" columns");
	m_rows++;

	mrpt::Clock::time_point t;
	if (const char* why = ContactLogFormat::parseTime(field(Column::TIME), t))
		fail(Column::TIME, quote(field(Column::TIME)) + " " + why);
	const double x = number(Column::ODOM_X), y = number(Column::ODOM_Y),
				 yaw = degrees(Column::ODOM_YAW_DEG);
	if (m_sweep.count == 0)
	{
		if (m_lastLine > 0 && t < m_lastTime)
			fail(
				Column::TIME, "time goes backwards: " + quote(field(Column::TIME)) +
								  " is before the previous sweep's (line " +
								  std::to_string(m_lastLine) + ")");
		m_sweep.obs = m_robot.blankSweep(m_noise, t);
		m_sweep.time = t;
		m_sweep.x = x, m_sweep.y = y, m_sweep.yaw = yaw;
		m_sweep.line = m_line;
		m_sweep.whiskerLine.assign(m_robot.whiskers.size(), 0);
	}
	else
		checkSameSweep(t, x, y, yaw);

	const auto w = field(Column::WHISKER);
	long index = -1;
	const auto r = std::from_chars(w.data(), w.data() + w.size(), index);
	if (r.ec != std::errc() || r.ptr != w.data() + w.size() || index < 0)
		fail(Column::WHISKER, quote(w) + " is not a whisker index (0, 1, 2, ...)");
	const size_t n = m_robot.whiskers.size();
	if (size_t(index) >= n)
		fail(
			Column::WHISKER, "whisker " + std::to_string(index) + " is not one of the robot's " +
								 std::to_string(n) + " (0.." + std::to_string(n - 1) + ")");
	auto& seen = m_sweep.whiskerLine[size_t(index)];
	if (seen)
		fail(
			Column::WHISKER,
			"whisker " + std::to_string(index) + " appears twice in the sweep starting at line " +
				std::to_string(m_sweep.line) + " (first at line " + std::to_string(seen) + ")");
	seen = m_line;
	readReading(m_sweep.obs->whiskers[size_t(index)], size_t(index));
	m_sweep.count++;
}

void ContactLogReader::checkSameSweep(
	mrpt::Clock::time_point t, double x, double y, double yaw) const
{
	auto differs = [&](Column c)
	{
		fail(
			c, quote(field(c)) + " differs from the sweep starting at line " +
				   std::to_string(m_sweep.line) + ", which still lacks whiskers " +
				   missingWhiskers() +
				   " (the rows of a sweep share time and odometry, one row per whisker)");
	};
	if (t != m_sweep.time) differs(Column::TIME);
	if (x != m_sweep.x) differs(Column::ODOM_X);
	if (y != m_sweep.y) differs(Column::ODOM_Y);
	if (yaw != m_sweep.yaw) differs(Column::ODOM_YAW_DEG);
}

void ContactLogReader::readReading(obs::TWhisker& w, size_t index)
{
	const auto touched = field(Column::TOUCHED);
	if (touched != "0" && touched != "1") fail(Column::TOUCHED, quote(touched) + " is not 0 or 1");
	if (touched == "0") return;	 // untouched: the blank sweep's readings stand
	auto who = [&] { return "whisker " + std::to_string(index) + "'s "; };	// for messages
	w.touched = true;
	w.angle = degrees(Column::ANGLE_DEG);
	const double lo = std::min(w.sweep_start, w.sweep_end),
				 hi = std::max(w.sweep_start, w.sweep_end);
	if (w.angle < lo - ANGLE_TOL || w.angle > hi + ANGLE_TOL)
		fail(
			Column::ANGLE_DEG, quote(field(Column::ANGLE_DEG)) + " deg is outside " + who() +
								   "sweep [" + deg(lo) + ", " + deg(hi) + "] deg");
	w.r = number(Column::R);
	if (w.r < 0) fail(Column::R, quote(field(Column::R)) + " m is negative");
	if (w.r > w.length)
		fail(
			Column::R,
			quote(field(Column::R)) + " m is past " + who() + "length " + num(w.length) + " m");
	w.normal = degrees(Column::NORMAL_DEG);
	w.texture = number(Column::TEXTURE);
	if (w.texture < 0 || w.texture > 1)
		fail(Column::TEXTURE, quote(field(Column::TEXTURE)) + " is not in [0, 1]");
}

std::string ContactLogReader::missingWhiskers() const
{
	std::string s;
	size_t listed = 0, missing = 0;
	for (size_t i = 0; i < m_sweep.whiskerLine.size(); i++)
	{
		if (m_sweep.whiskerLine[i]) continue;
		missing++;
		if (listed++ < 8) s += (s.empty() ? "" : ", ") + std::to_string(i);
	}
	return listed > 8 ? s + ", ... (" + std::to_string(missing) + " in all)" : s;
}
}  // namespace whiskermap::world
