#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TableCsv.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
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

/** Reads `path`, checks its header is `header`, then calls `onRow` for each data line
 *  after checking its column count. */
void readCsv(const std::string& path, const std::string& header, const std::function<void(const Row&)>& onRow)
{
	if (!std::filesystem::is_regular_file(path)) throw core::Error(path + ": no such file");
	std::ifstream in(path);
	if (!in) throw core::Error(path + ": cannot read file");
	const auto names = split(header);
	std::string line;
	size_t n = 1;
	for (; std::getline(in, line); n++)
	{
		if (!line.empty() && line.back() == '\r') line.pop_back();
		const std::string where = path + ": line " + std::to_string(n) + ": ";
		if (n == 1)
		{
			if (line != header)
				throw core::Error(where + "bad header '" + line + "' (expected '" + header + "')");
			continue;
		}
		auto fields = split(line);
		if (fields.size() != names.size())
			throw core::Error(
				where + "expected " + std::to_string(names.size()) + " columns, got " +
				std::to_string(fields.size()));
		onRow(Row(names, std::move(fields), where));
	}
	if (in.bad()) throw core::Error(path + ": read error");
	if (n == 1) throw core::Error(path + ": empty file (expected the header '" + header + "')");
}
}  // namespace

std::vector<TableCsv::MapRow> TableCsv::readMap(const std::string& path)
{
	std::vector<MapRow> rows;
	std::set<long> ids;
	readCsv(path, MAP_HEADER, [&](const Row& r) {
		MapRow m;
		m.id = r.integer(0, 1e9);
		m.table = r.table();
		m.existence = r.number(8, 0, 1);
		m.contacts = static_cast<uint64_t>(r.integer(9, 1e15));
		m.legs = static_cast<uint32_t>(r.integer(10, 4));
		if (!ids.insert(m.id).second) r.fail("duplicate id " + std::to_string(m.id));
		rows.push_back(m);
	});
	return rows;
}

std::vector<std::vector<world::Table>> TableCsv::readPerPose(const std::string& path, size_t poses)
{
	std::vector<std::vector<world::Table>> perPose(poses);
	readCsv(path, PER_POSE_HEADER, [&](const Row& r) {
		const long pose = r.integer(0, 1e9);
		const world::Table t = r.table();
		r.number(8, -INFINITY, INFINITY);  // log_posterior: checked, not used
		if (size_t(pose) >= poses)
			r.fail("pose " + std::to_string(pose) + " out of range (" + std::to_string(poses) + " poses)");
		perPose[pose].push_back(t);
	});
	return perPose;
}

std::vector<world::Table> TableCsv::tables(const std::vector<MapRow>& rows)
{
	std::vector<world::Table> out;
	for (const auto& r : rows) out.push_back(r.table);
	return out;
}
}  // namespace whiskermap::eval
