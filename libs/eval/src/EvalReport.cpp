#include <whiskermap/eval/EvalReport.h>

#include <cstdio>
#include <utility>
#include <vector>

namespace whiskermap::eval
{
namespace
{
/** The figures in report order: JSON key, human label, field. */
struct FigureRow
{
	const char* key;
	const char* label;
	double Figures::*field;
};
const FigureRow FIGURE_ROWS[] = {
	{"precision", "precision", &Figures::precision},
	{"recall", "recall", &Figures::recall},
	{"f1", "F1", &Figures::f1},
	{"rmse_m", "centre RMSE (m)", &Figures::rmse_m},
	{"yaw_err_deg", "yaw error (deg)", &Figures::yaw_err_deg},
	{"ospa", "OSPA (m)", &Figures::ospa},
	{"count_error", "count error", &Figures::count_error},
};

/** `v` with `decimals` decimals, or `undefined` when NaN. */
std::string num(double v, int decimals, const char* undefined = "null")
{
	if (std::isnan(v)) return undefined;
	char buf[64];
	std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
	return buf;
}

using Fields = std::vector<std::pair<std::string, std::string>>;  // key, JSON value

std::string object(const Fields& fields, int indent)
{
	const std::string pad(indent + 2, ' ');
	std::string s = "{\n";
	for (size_t i = 0; i < fields.size(); i++)
		s += pad + "\"" + fields[i].first + "\": " + fields[i].second +
			 (i + 1 < fields.size() ? ",\n" : "\n");
	return s + std::string(indent, ' ') + "}";
}

/** The figures; count_error with `countDecimals` (0 for a single map: it is a whole number). */
Fields figureFields(const Figures& f, int countDecimals)
{
	Fields out;
	for (const auto& r : FIGURE_ROWS)
		out.emplace_back(r.key, num(f.*r.field, r.field == &Figures::count_error ? countDecimals : 6));
	return out;
}
}  // namespace

std::string EvalReport::toJson() const
{
	Fields top = figureFields(map.figures, 0);
	top.emplace_back("estimated", std::to_string(map.estimated));
	top.emplace_back("truth", std::to_string(map.truth));
	top.emplace_back("matched", std::to_string(map.matched));
	if (identifiability)
	{
		top.emplace_back("identifiable_tables", std::to_string(identifiability->tables.size()));
		top.emplace_back("recall_identifiable", num(identifiability->recall(map), 6));
	}
	if (perPose)
	{
		Fields pp{{"poses", std::to_string(perPose->poses)}};
		for (auto& f : figureFields(perPose->all, 6)) pp.push_back(std::move(f));
		if (perPose->local) pp.emplace_back("local", object(figureFields(*perPose->local, 6), 4));
		top.emplace_back("per_pose", object(pp, 2));
	}
	return object(top, 0) + "\n";
}

std::string EvalReport::toText() const
{
	char buf[256];
	std::string s;
	std::snprintf(
		buf, sizeof(buf),
		"map: %zu tables estimated, %zu true, %zu matched (gates %.3g m, %.3g deg; "
		"OSPA c = %.3g m, p = %.3g)\n",
		map.estimated, map.truth, map.matched, options.gate_distance, options.gate_yaw_deg,
		options.ospa_c, options.ospa_p);
	s += buf;
	std::vector<std::pair<const char*, const Figures*>> columns{{"map", &map.figures}};
	if (perPose) columns.emplace_back("per-pose", &perPose->all);
	if (perPose && perPose->local) columns.emplace_back("per-pose local", &*perPose->local);
	std::snprintf(buf, sizeof(buf), "%-16s", "");
	s += buf;
	for (const auto& c : columns)
	{
		std::snprintf(buf, sizeof(buf), " %15s", c.first);
		s += buf;
	}
	s += "\n";
	for (const auto& r : FIGURE_ROWS)
	{
		std::snprintf(buf, sizeof(buf), "%-16s", r.label);
		s += buf;
		for (const auto& c : columns)
		{
			std::snprintf(buf, sizeof(buf), " %15s", num(c.second->*r.field, 3, "n/a").c_str());
			s += buf;
		}
		s += "\n";
	}
	if (perPose)
	{
		std::snprintf(buf, sizeof(buf), "per-pose: averaged over %zu poses", perPose->poses);
		s += buf;
		if (perPose->local)
		{
			std::snprintf(buf, sizeof(buf), "; local truth: tables within %.3g m of the robot", options.local_radius);
			s += buf;
		}
		s += "\n";
	}
	if (identifiability)
	{
		std::snprintf(
			buf, sizeof(buf),
			"identifiable tables (touched on >= 2 legs, gate %.3f m): %zu; recall on them %.3f\n",
			identifiability->gate, identifiability->tables.size(), identifiability->recall(map));
		s += buf;
	}
	return s;
}
}  // namespace whiskermap::eval
