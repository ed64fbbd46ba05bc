#include <whiskermap/core/Angles.h>
#include <whiskermap/eval/EvalReport.h>

#include <cstdio>
#include <utility>
#include <vector>

#include "JsonNumber.h"

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
	{"rmse_aligned_m", "centre RMSE aligned (m)", &Figures::rmse_aligned_m},
	{"yaw_err_deg", "yaw error (deg)", &Figures::yaw_err_deg},
	{"ospa", "OSPA (m)", &Figures::ospa},
	{"count_error", "count error", &Figures::count_error},
};

using detail::num;

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

/** The trajectory figures in report order (JSON). */
Fields trajectoryFields(const TrajectoryEvaluation& t, const EvalOptions& o)
{
	return {
		{"poses", std::to_string(t.poses)},
		{"length_m", num(t.length_m, 6)},
		{"ate_rmse_m", num(t.ate_rmse_m, 6)},
		{"ate_max_m", num(t.ate_max_m, 6)},
		{"ate_yaw_rmse_deg", num(t.ate_yaw_rmse_deg, 6)},
		{"aligned_rmse_m", num(t.aligned_rmse_m, 6)},
		{"aligned_max_m", num(t.aligned_max_m, 6)},
		{"alignment_yaw_deg", num(core::rad2deg(t.alignment.yaw), 6)},
		{"alignment_x_m", num(t.alignment.t.x(), 6)},
		{"alignment_y_m", num(t.alignment.t.y(), 6)},
		{"rpe_segment_m", num(o.rpe_segment_m, 6)},
		{"rpe_segments", std::to_string(t.rpe_segments)},
		{"rpe_trans", num(t.rpe_trans, 6)},
		{"rpe_rot_deg_per_m", num(t.rpe_rot_deg_per_m, 6)},
		{"final_error_m", num(t.final_error_m, 6)},
		{"final_yaw_err_deg", num(t.final_yaw_err_deg, 6)},
	};
}

/** Class accuracy and dimension errors (maps whose objects carry a class). */
Fields classFields(const ClassFigures& c)
{
	return {
		{"matched_any_class", std::to_string(c.matched_any_class)},
		{"class_accuracy", num(c.class_accuracy, 6)},
		{"length_err_m", num(c.length_err_m, 6)},
		{"width_err_m", num(c.width_err_m, 6)},
		{"leg_width_err_m", num(c.leg_width_err_m, 6)},
		{"leg_width_bias_m", num(c.leg_width_bias_m, 6)},
		{"texture_err", num(c.texture_err, 6)},
	};
}

Fields wallFields(const WallEvaluation& w)
{
	Fields f{
		{"gate_m", num(w.gate_m, 6)},
		{"true_length_m", num(w.true_length_m, 6)},
		{"estimated_length_m", num(w.estimated_length_m, 6)},
		{"recall", num(w.recall, 6)},
		{"precision", num(w.precision, 6)},
	};
	if (w.touched_known)
	{
		f.emplace_back("touched_length_m", num(w.touched_length_m, 6));
		f.emplace_back("recall_touched", num(w.recall_touched, 6));
	}
	return f;
}

std::string trajectoryText(const TrajectoryEvaluation& t, const EvalOptions& o)
{
	char buf[512];
	std::snprintf(
		buf, sizeof(buf),
		"trajectory: %zu poses, %.3f m of true travel\n"
		"%-24s %10s %10s\n"
		"%-24s %10.4f %10.4f\n"
		"%-24s %10.4f %10.4f\n"
		"%-24s %10.3f\n"
		"alignment (estimate onto truth): yaw %.3f deg, shift (%.4f, %.4f) m\n"
		"RPE over %zu segments of >= %.3g m: %s m/m, %s deg/m\n"
		"final pose error: %.4f m, %.3f deg\n",
		t.poses, t.length_m, "", "raw", "aligned", "ATE RMSE (m)", t.ate_rmse_m, t.aligned_rmse_m,
		"ATE max (m)", t.ate_max_m, t.aligned_max_m, "heading RMSE (deg)", t.ate_yaw_rmse_deg,
		core::rad2deg(t.alignment.yaw), t.alignment.t.x(), t.alignment.t.y(), t.rpe_segments,
		o.rpe_segment_m, num(t.rpe_trans, 4, "n/a").c_str(), num(t.rpe_rot_deg_per_m, 3, "n/a").c_str(),
		t.final_error_m, t.final_yaw_err_deg);
	return buf;
}
}  // namespace

std::string EvalReport::toJson() const
{
	Fields top;
	if (map)
	{
		top = figureFields(map->figures, 0);
		top.emplace_back("estimated", std::to_string(map->estimated));
		top.emplace_back("truth", std::to_string(map->truth));
		top.emplace_back("matched", std::to_string(map->matched));
		if (map->classes)
			for (auto& f : classFields(*map->classes)) top.push_back(std::move(f));
		if (objectsOnWalls) top.emplace_back("objects_on_walls", std::to_string(*objectsOnWalls));
	}
	if (map && identifiability)
	{
		top.emplace_back("identifiable_tables", std::to_string(identifiability->tables.size()));
		top.emplace_back("recall_identifiable", num(identifiability->recall(*map), 6));
	}
	if (perPose)
	{
		Fields pp{{"poses", std::to_string(perPose->poses)}};
		for (auto& f : figureFields(perPose->all, 6)) pp.push_back(std::move(f));
		if (perPose->local) pp.emplace_back("local", object(figureFields(*perPose->local, 6), 4));
		top.emplace_back("per_pose", object(pp, 2));
	}
	if (walls) top.emplace_back("walls", object(wallFields(*walls), 2));
	if (trajectory) top.emplace_back("trajectory", object(trajectoryFields(*trajectory, options), 2));
	if (calibration) top.emplace_back("calibration", calibration->toJson(2));
	if (spread) top.emplace_back("pose_spread", spread->toJson(2));
	return object(top, 0) + "\n";
}

std::string EvalReport::toText() const
{
	std::string s = map ? mapText() : "";
	if (walls)
	{
		char buf[256];
		std::snprintf(
			buf, sizeof(buf), "walls (gate %.3g m): %.3f m true, %.3f m estimated; length recall %.3f, precision %.3f\n",
			walls->gate_m, walls->true_length_m, walls->estimated_length_m, walls->recall, walls->precision);
		s += buf;
		if (walls->touched_known)
		{
			std::snprintf(
				buf, sizeof(buf), "walls touched by the whiskers: %.3f m; length recall on them %.3f\n",
				walls->touched_length_m, walls->recall_touched);
			s += buf;
		}
	}
	if (trajectory) s += trajectoryText(*trajectory, options);
	if (calibration) s += calibration->toText();
	if (spread) s += spread->toText();
	return s;
}

std::string EvalReport::mapText() const
{
	char buf[256];
	std::string s;
	std::snprintf(
		buf, sizeof(buf),
		"map: %zu tables estimated, %zu true, %zu matched (gates %.3g m, %.3g deg; "
		"OSPA c = %.3g m, p = %.3g)\n",
		map->estimated, map->truth, map->matched, options.gate_distance, options.gate_yaw_deg,
		options.ospa_c, options.ospa_p);
	s += buf;
	std::vector<std::pair<const char*, const Figures*>> columns{{"map", &map->figures}};
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
			identifiability->gate, identifiability->tables.size(), identifiability->recall(*map));
		s += buf;
	}
	if (map->classes)
	{
		const auto& c = *map->classes;
		std::snprintf(
			buf, sizeof(buf),
			"classes: %zu matched ignoring the class, class accuracy %s; dimension errors (m): length %s, width %s, leg %s "
			"(bias %s); texture error %s\n",
			c.matched_any_class, num(c.class_accuracy, 3, "n/a").c_str(), num(c.length_err_m, 4, "n/a").c_str(),
			num(c.width_err_m, 4, "n/a").c_str(), num(c.leg_width_err_m, 4, "n/a").c_str(),
			num(c.leg_width_bias_m, 4, "n/a").c_str(),
			num(c.texture_err, 3, "n/a").c_str());
		s += buf;
	}
	if (objectsOnWalls)
	{
		std::snprintf(buf, sizeof(buf), "objects on a wall: %zu\n", *objectsOnWalls);
		s += buf;
	}
	return s;
}
}  // namespace whiskermap::eval
