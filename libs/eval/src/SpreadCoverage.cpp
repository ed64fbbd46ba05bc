#include <whiskermap/core/Angles.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/SpreadCoverage.h>

#include <cmath>
#include <cstdio>

#include "JsonNumber.h"

namespace whiskermap::eval
{
namespace
{
constexpr const char* AXES[3] = {"x", "y", "yaw"};
}  // namespace
using detail::num;

void SpreadCoverage::add(const std::array<double, 3>& error, const std::array<double, 3>& sd)
{
	m_count++;
	for (size_t a = 0; a < 3; a++)
	{
		const double e = std::abs(error[a]);
		m_axes[a].within1 += e <= sd[a];
		m_axes[a].within2 += e <= 2 * sd[a];
		m_axes[a].sumZ2 += sd[a] > 0 ? (e / sd[a]) * (e / sd[a]) : (e > 0 ? INFINITY : 0);
	}
}

void SpreadCoverage::add(const SpreadCoverage& other)
{
	m_count += other.m_count;
	for (size_t a = 0; a < 3; a++)
	{
		m_axes[a].within1 += other.m_axes[a].within1;
		m_axes[a].within2 += other.m_axes[a].within2;
		m_axes[a].sumZ2 += other.m_axes[a].sumZ2;
	}
}

SpreadCoverage SpreadCoverage::of(
	const std::vector<world::Table>& truth, const std::vector<TableCsv::MapRow>& rows, const EvalOptions& opts,
	bool hasClass)
{
	return of(truth, rows, MapEvaluation::compute(truth, TableCsv::tables(rows), opts, hasClass).truthMatch);
}

SpreadCoverage SpreadCoverage::of(
	const std::vector<world::Table>& truth, const std::vector<TableCsv::MapRow>& rows,
	const std::vector<int>& truthMatch)
{
	SpreadCoverage c;
	for (size_t i = 0; i < truth.size(); i++)
	{
		if (truthMatch[i] < 0) continue;
		const TableCsv::MapRow& r = rows[static_cast<size_t>(truthMatch[i])];
		if (!r.spread) continue;
		c.add({r.table.x - truth[i].x, r.table.y - truth[i].y, MapEvaluation::yawError(truth[i], r.table)},
			  {r.spread->x, r.spread->y, core::deg2rad(r.spread->yaw_deg)});
	}
	return c;
}

double SpreadCoverage::within(size_t a, int k) const
{
	if (m_count == 0) return NAN;
	return static_cast<double>(k == 1 ? m_axes[a].within1 : m_axes[a].within2) / static_cast<double>(m_count);
}

double SpreadCoverage::rmsZ(size_t a) const
{
	return m_count == 0 ? NAN : std::sqrt(m_axes[a].sumZ2 / static_cast<double>(m_count));
}

std::string SpreadCoverage::toJson(int indent) const
{
	const std::string pad(indent + 2, ' ');
	std::string s = "{\n" + pad + "\"objects\": " + std::to_string(m_count);
	for (size_t a = 0; a < 3; a++)
		s += ",\n" + pad + "\"" + AXES[a] + "\": {\"within_1sd\": " + num(within(a, 1)) + ", \"within_2sd\": " +
			 num(within(a, 2)) + ", \"rms_z\": " + num(rmsZ(a)) + "}";
	return s + "\n" + std::string(indent, ' ') + "}";
}

std::string SpreadCoverage::toText() const
{
	char buf[160];
	std::snprintf(buf, sizeof(buf), "pose spread: %zu matched objects; fraction within 1 / 2 sd, rms error / sd\n", m_count);
	std::string s = buf;
	for (size_t a = 0; a < 3; a++)
	{
		std::snprintf(buf, sizeof(buf), "  %-4s %s / %s, %s\n", AXES[a], num(within(a, 1)).c_str(),
					  num(within(a, 2)).c_str(), num(rmsZ(a)).c_str());
		s += buf;
	}
	return s;
}
}  // namespace whiskermap::eval
