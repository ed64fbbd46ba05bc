#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/LineReader.h>
#include <whiskermap/eval/TableCsv.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

namespace whiskermap::eval
{
namespace
{
std::vector<std::string> split(const std::string& line)
{
	std::vector<std::string> fields;
	std::stringstream ss(line);
	std::string f;
	while (std::getline(ss, f, ',')) fields.push_back(f);
	if (!line.empty() && line.back() == ',') fields.emplace_back();
	return fields;
}

/** One data row being checked: typed, range-checked access to its columns by name. */
class Row
{
   public:
	Row(std::vector<std::string> names, std::vector<std::string> fields, std::string where)
		: m_names(std::move(names)), m_fields(std::move(fields)), m_where(std::move(where))
	{
	}

	[[noreturn]] void fail(const std::string& problem) const { throw core::Error(m_where + problem); }

	const std::string& text(size_t col) const { return m_fields[col]; }
	size_t size() const { return m_fields.size(); }

	double number(size_t col, double lo, double hi) const
	{
		const std::string& s = m_fields[col];
		const std::string what = "column '" + m_names[col] + "': '" + s + "' ";
		char* end = nullptr;
		const double v = s.empty() || std::isspace(static_cast<unsigned char>(s[0]))
			? NAN : std::strtod(s.c_str(), &end);
		if (end != s.c_str() + s.size()) fail(what + "is not a number");
		if (!std::isfinite(v)) fail(what + "is not finite");
		if (v < lo || v > hi) fail(what + "is out of range [" + fmt(lo) + ", " + fmt(hi) + "]");
		return v;
	}

	long integer(size_t col, double hi) const
	{
		const double v = number(col, 0, hi);
		if (v != std::floor(v))
			fail("column '" + m_names[col] + "': '" + m_fields[col] + "' is not a whole number");
		return static_cast<long>(v);
	}

	/** Columns 1..7: x, y, yaw_deg, length, width, leg_width, texture. */
	world::Table table() const
	{
		const double big = 1e4;
		world::Table t;
		t.x = number(1, -big, big);
		t.y = number(2, -big, big);
		t.yaw = core::deg2rad(number(3, -big, big));
		t.length = number(4, 1e-6, big);
		t.width = number(5, 1e-6, big);
		t.leg_width = number(6, 1e-6, big);
		t.texture = number(7, 0, 1);
		return t;
	}

   private:
	static std::string fmt(double v)
	{
		std::ostringstream o;
		o << v;
		return o.str();
	}
	std::vector<std::string> m_names, m_fields;
	std::string m_where;
};

/** Reads a CSV in bounded memory: checks the header, then gives one checked row at a time. */
class CsvReader
{
   public:
	/** The file's header must be one of `headers` (the first is the one an error names). */
	CsvReader(const std::string& path, const std::vector<std::string>& headers)
		: m_in(path, "file"), m_path(path), m_header(headers.front())
	{
		std::string line;
		if (!m_in.next(line)) throw core::Error(path + ": empty file (expected the header '" + m_header + "')");
		if (std::find(headers.begin(), headers.end(), line) == headers.end())
			throw core::Error(m_in.where() + "bad header '" + line + "' (expected '" + m_header + "')");
		m_names = split(line);
	}
	const std::vector<std::string>& names() const { return m_names; }
	/** The next data row (its column count checked); empty optional at the end. */
	std::optional<Row> next()
	{
		std::string line;
		if (!m_in.next(line)) return std::nullopt;
		auto fields = split(line);
		if (fields.size() != m_names.size())
			throw core::Error(
				m_in.where() + "expected " + std::to_string(m_names.size()) + " columns, got " + std::to_string(fields.size()));
		return Row(m_names, std::move(fields), m_in.where());
	}

   private:
	core::LineReader m_in;
	std::string m_path, m_header;
	std::vector<std::string> m_names;
};

/** Calls onRow on every row; returns the column names of the header found (one of `headers`). */
std::vector<std::string> readCsv(
	const std::string& path, const std::vector<std::string>& headers, const std::function<void(const Row&)>& onRow)
{
	CsvReader in(path, headers);
	while (const auto row = in.next()) onRow(*row);
	return in.names();
}


}  // namespace

std::vector<TableCsv::MapRow> TableCsv::readMap(const std::string& path, bool* hasClass)
{
	std::vector<MapRow> rows;
	std::set<long> ids;
	const auto names = readCsv(path, {MAP_HEADER, MAP_HEADER_CLASS, MAP_HEADER_SPREAD, MAP_HEADER_SPREAD_CLASS}, [&](const Row& r) {
		const bool withSpread = r.size() >= 14, withClass = r.size() == 12 || r.size() == 15;
		MapRow m;
		m.id = r.integer(0, 1e9);
		m.table = r.table();
		if (withClass)
		{
			const std::string& name = r.text(r.size() - 1);
			if (!world::ObjectClass::valid(name))
				r.fail("column 'class': '" + name + "' is not a class name (1 to 31 letters, digits or _)");
			m.table.object_class = world::ObjectClass(name);
		}
		m.existence = r.number(8, 0, 1);
		m.contacts = static_cast<uint64_t>(r.integer(9, 1e15));
		m.legs = static_cast<uint32_t>(r.integer(10, 4));
		if (withSpread) m.spread = MapRow::Spread{r.number(11, 0, 1e4), r.number(12, 0, 1e4), r.number(13, 0, 180)};
		if (!ids.insert(m.id).second) r.fail("duplicate id " + std::to_string(m.id));
		rows.push_back(m);
	});
	if (hasClass) *hasClass = names.back() == "class";
	return rows;
}

std::vector<TableCsv::WallRow> TableCsv::readWalls(const std::string& path)
{
	std::vector<WallRow> rows;
	readCsv(path, {WALLS_HEADER}, [&](const Row& r) {
		const double big = 1e4;
		WallRow w;
		w.wall.x0 = r.number(0, -big, big);
		w.wall.y0 = r.number(1, -big, big);
		w.wall.x1 = r.number(2, -big, big);
		w.wall.y1 = r.number(3, -big, big);
		w.wall.thickness = r.number(4, 0, big);
		w.existence = r.number(5, 0, 1);
		if (w.wall.length() <= 0) r.fail("wall of zero length");
		rows.push_back(w);
	});
	return rows;
}

struct TableCsv::PerPoseReader::Impl
{
	Impl(const std::string& path, size_t n) : in(path, {PER_POSE_HEADER}), poses(n) {}
	CsvReader in;
	size_t poses, next = 0;  ///< the pose next() gives next
	std::optional<std::pair<size_t, world::Table>> pending;  ///< a row read ahead
	size_t lastPose = 0;
	bool any = false;

	/** Reads the next row into `pending` (checked: range and order). */
	void readAhead()
	{
		const auto r = in.next();
		if (!r) return;
		const long pose = r->integer(0, 1e9);
		const world::Table t = r->table();
		r->number(8, -INFINITY, INFINITY);  // log_posterior: checked, not used
		if (size_t(pose) >= poses)
			r->fail("pose " + std::to_string(pose) + " out of range (" + std::to_string(poses) + " poses)");
		if (any && size_t(pose) < lastPose)
			r->fail("pose " + std::to_string(pose) + " after pose " + std::to_string(lastPose) +
					" (rows must be in pose order, as whisker-map writes them)");
		lastPose = size_t(pose), any = true;
		pending.emplace(size_t(pose), t);
	}
};

TableCsv::PerPoseReader::PerPoseReader(const std::string& path, size_t poses) : m(std::make_unique<Impl>(path, poses))
{
	m->readAhead();
}

TableCsv::PerPoseReader::~PerPoseReader() = default;

bool TableCsv::PerPoseReader::next(std::vector<world::Table>& tables)
{
	tables.clear();
	if (m->next == m->poses) return false;
	while (m->pending && m->pending->first == m->next)
	{
		tables.push_back(m->pending->second);
		m->pending.reset();
		m->readAhead();
	}
	m->next++;
	return true;
}

std::vector<std::vector<world::Table>> TableCsv::readPerPose(const std::string& path, size_t poses)
{
	std::vector<std::vector<world::Table>> perPose;
	PerPoseReader r(path, poses);
	std::vector<world::Table> tables;
	while (r.next(tables)) perPose.push_back(tables);
	return perPose;
}

std::vector<world::Table> TableCsv::tables(const std::vector<MapRow>& rows)
{
	std::vector<world::Table> out;
	for (const auto& r : rows) out.push_back(r.table);
	return out;
}
}  // namespace whiskermap::eval
