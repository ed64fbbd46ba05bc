#include <whiskermap/core/Angles.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/ObjectCatalogue.h>

#include <filesystem>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace whiskermap::model
{
ModelParams ModelParams::fromIni(core::IniSection& sec)
{
	constexpr double BIG = 1e30;
	ModelParams p;
	p.sigma_r = sec.number("sigma_r", 1e-6, 10);
	p.sigma_theta = sec.number("sigma_theta", 1e-6, M_PI);
	p.sigma_w = sec.number("sigma_w", 1e-6, 10);
	p.sigma_tau = sec.number("sigma_tau", 1e-6, 10);
	p.sigma_corner = sec.number("sigma_corner", p.sigma_r, 1e-6, 10);
	p.shaft_noise = sec.boolean("shaft_noise", false);
	p.sigma_across = sec.number("sigma_across", 0.002, 1e-6, 10);
	p.c_T = sec.number("c_T", 1e-300, BIG);
	p.c_L = sec.number("c_L", 1e-300, BIG);
	p.c_S = sec.number("c_S", 1e-300, BIG);
	p.alpha_L = sec.number("alpha_L", 1e-300, BIG);
	p.alpha_S = sec.number("alpha_S", 1e-300, BIG);
	p.epsilon = sec.number("epsilon", 1e-300, 1);
	p.delta = sec.number("delta", 1e-9, 1);
	p.table_length = sec.number("table_length", 1e-3, 100);
	p.table_width = sec.number("table_width", 1e-3, 100);
	p.leg_width = sec.number("leg_width", 1e-4, 10);
	p.texture = sec.number("texture", 0, 1);
	p.parent_gate = sec.number("parent_gate", 1e-6, 100);
	p.free_space = sec.boolean("free_space", p.free_space);
	p.free_space_p_miss = sec.number("free_space_p_miss", p.free_space_p_miss, 1e-12, 1);
	p.walls = sec.boolean("walls", p.walls);
	p.c_W = sec.number("c_W", p.c_W, 1e-300, BIG);
	p.wall_length_scale = sec.number("wall_length_scale", p.wall_length_scale, 1e-3, 1e6);
	p.wall_thickness = sec.number("wall_thickness", p.wall_thickness, 1e-3, 10);
	p.manhattan_walls = sec.boolean("manhattan_walls", p.manhattan_walls);
	p.wall_axis = core::deg2rad(sec.number("wall_axis_deg", core::rad2deg(p.wall_axis), -90, 90));
	const std::string objects = sec.text("objects", "");
	p.size_moves = sec.boolean("size_moves", p.size_moves);
	sec.finish();
	if (!objects.empty())
	{
		const std::filesystem::path rel(objects);
		const auto dir = std::filesystem::path(sec.fileLabel()).parent_path();
		p.classes = ObjectCatalogue::load(rel.is_absolute() ? objects : (dir / rel).string());
	}
	if (p.size_moves && p.classes.empty()) sec.fail("size_moves", "needs an object catalogue (the key objects)");
	if (p.leg_width >= std::min(p.table_length, p.table_width))
		sec.fail("leg_width", "must be smaller than table_length and table_width");
	return p;
}

bool ModelParams::legsVary() const
{
	return std::any_of(classes.begin(), classes.end(), [](const ObjectClass& c) { return c.legsVary(); });
}

double ModelParams::maxDiagonal() const
{
	double d = 0;
	for (int k = 0; k < classCount(); k++) d = std::max(d, std::hypot(lengthOf(k), widthOf(k)));
	return d;
}

double ModelParams::maxLength() const
{
	double d = 0;
	for (int k = 0; k < classCount(); k++) d = std::max(d, lengthOf(k));
	return d;
}

bool ModelParams::operator==(const ModelParams& o) const
{
	auto tie = [](const ModelParams& p) {
		return std::tie(
			p.sigma_r, p.sigma_theta, p.sigma_w, p.sigma_tau, p.sigma_corner, p.shaft_noise, p.sigma_across, p.c_T, p.c_L, p.c_S,
			p.alpha_L, p.alpha_S, p.epsilon, p.delta, p.table_length, p.table_width, p.leg_width, p.texture,
			p.parent_gate, p.free_space, p.free_space_p_miss, p.walls, p.c_W, p.wall_length_scale, p.wall_thickness,
			p.manhattan_walls, p.wall_axis,
			p.classes, p.size_moves);
	};
	return tie(*this) == tie(o);
}
}  // namespace whiskermap::model
