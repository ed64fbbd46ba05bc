#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/world/World.h>

#include "WorldSections.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace whiskermap::world
{
using core::Error;

World World::load(const std::string& path)
{
	const auto file = core::openIniFile(path, "world file");
	const auto& cfg = *file;
	std::vector<std::string> sections;  // [arena], [table_N] and [wall_N] only
	cfg.getAllSections(sections);
	for (const auto& s : sections)
		if (!s.empty() && s != "arena" && s.rfind("table_", 0) != 0 && s.rfind("wall_", 0) != 0)
			throw Error(core::iniWhere(cfg, s, "", path) + "[" + s + "]: unknown section");

	World w;
	core::IniSection arena(cfg, "arena", path);
	if (!cfg.sectionExists("arena")) arena.fail("", "missing section");
	const double big = 1e4;
	w.x_min = arena.number("x_min", -big, big);
	w.x_max = arena.number("x_max", -big, big);
	w.y_min = arena.number("y_min", -big, big);
	w.y_max = arena.number("y_max", -big, big);
	w.wall_texture = arena.number("wall_texture", w.wall_texture, 0, 1);
	arena.finish();
	if (w.x_max <= w.x_min) arena.fail("x_max", "must be greater than x_min");
	if (w.y_max <= w.y_min) arena.fail("y_max", "must be greater than y_min");

	const auto wallNames = detail::readWalls(cfg, path, w);
	detail::readTables(cfg, path, wallNames, w);
	return w;
}

void World::save(const std::string& path, const std::string& comment) const
{
	std::ofstream f(path);
	if (!f) throw Error(path + ": cannot write file");
	f << "; whiskermap world (format: doc/formats.md)\n";
	std::istringstream lines(comment);
	for (std::string line; std::getline(lines, line);) f << "; " << line << "\n";
	char buf[512];
	std::snprintf(
		buf, sizeof(buf),
		"[arena]\nx_min=%.10g\nx_max=%.10g\ny_min=%.10g\ny_max=%.10g\nwall_texture=%.10g\n",
		x_min, x_max, y_min, y_max, wall_texture);
	f << buf;
	for (size_t i = 0; i < tables.size(); i++)
	{
		const auto& t = tables[i];
		std::snprintf(
			buf, sizeof(buf),
			"\n[table_%zu]\nx=%.10g\ny=%.10g\nyaw_deg=%.10g\nlength=%.10g\nwidth=%.10g\n"
			"leg_width=%.10g\ntexture=%.10g\n",
			i, t.x, t.y, core::rad2deg(t.yaw), t.length, t.width, t.leg_width, t.texture);
		f << buf;
		if (t.object_class != ObjectClass()) f << "class=" << t.object_class.str() << "\n";  // default omitted
	}
	for (size_t i = 0; i < walls.size(); i++)
	{
		const auto& v = walls[i];
		std::snprintf(
			buf, sizeof(buf), "\n[wall_%zu]\nx0=%.10g\ny0=%.10g\nx1=%.10g\ny1=%.10g\nthickness=%.10g\ntexture=%.10g\n",
			i, v.x0, v.y0, v.x1, v.y1, v.thickness, v.texture);
		f << buf;
	}
	if (!f) throw Error(path + ": write failed");
}

World World::tiled(int nx, int ny) const
{
	World w = *this;
	const double dx = x_max - x_min, dy = y_max - y_min;
	w.x_max = x_min + nx * dx;
	w.y_max = y_min + ny * dy;
	w.tables.clear();
	w.walls.clear();
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++)
		{
			for (auto t : tables)
			{
				t.x += i * dx, t.y += j * dy;
				w.tables.push_back(t);
			}
			for (auto v : walls)
			{
				v.x0 += i * dx, v.x1 += i * dx, v.y0 += j * dy, v.y1 += j * dy;
				w.walls.push_back(v);
			}
		}
	return w;
}

std::vector<Obstacle> World::obstacles(double wallThickness) const
{
	std::vector<Obstacle> obs;
	for (size_t i = 0; i < tables.size(); i++)
		for (int k = 0; k < 4; k++) obs.push_back(tables[i].leg(k, static_cast<int>(i)));
	const double T = wallThickness, cx = (x_min + x_max) / 2, cy = (y_min + y_max) / 2;
	const double hx = (x_max - x_min) / 2 + T, hy = (y_max - y_min) / 2 + T;
	obs.push_back(Obstacle::rectangle({x_min - T / 2, cy}, 0, T / 2, hy, wall_texture));
	obs.push_back(Obstacle::rectangle({x_max + T / 2, cy}, 0, T / 2, hy, wall_texture));
	obs.push_back(Obstacle::rectangle({cx, y_min - T / 2}, 0, hx, T / 2, wall_texture));
	obs.push_back(Obstacle::rectangle({cx, y_max + T / 2}, 0, hx, T / 2, wall_texture));
	for (const auto& v : walls) obs.push_back(v.slab());
	return obs;
}
}  // namespace whiskermap::world
