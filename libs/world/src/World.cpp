#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/world/World.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

namespace whiskermap::world
{
using core::Error;

World World::load(const std::string& path)
{
	const auto file = core::openIniFile(path, "world file");
	const auto& cfg = *file;
	core::rejectUnknownSections(cfg, {"arena"}, "table_", path);

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

	// [table_N] sections, in order of N.
	std::map<long, std::string> byIndex;
	for (const auto& s : cfg.sectionsInOrder())
	{
		if (s.rfind("table_", 0) != 0) continue;
		const long n = core::sectionIndex(s, "table_", MAX_TABLES);
		if (n < 0)
			throw Error(core::iniWhere(cfg, s) + "[" + s + "]: table sections must be named table_N, N = 0, 1, ... " +
						"(no leading zeros, N < " + std::to_string(MAX_TABLES) + ")");
		byIndex[n] = s;
	}
	std::vector<std::string> names;
	struct Box
	{
		double x0, x1, y0, y1;
	};
	std::vector<Obstacle> feet;
	std::vector<Box> boxes;
	for (const auto& [index, name] : byIndex)
	{
		core::IniSection sec(cfg, name, path);
		Table t;
		t.x = sec.number("x", -big, big);
		t.y = sec.number("y", -big, big);
		t.yaw = core::deg2rad(sec.number("yaw_deg", -360, 360));
		t.length = sec.number("length", 1e-3, 100);
		t.width = sec.number("width", 1e-3, 100);
		t.leg_width = sec.number("leg_width", 1e-3, 10);
		t.texture = sec.number("texture", 0, 1);
		sec.finish();
		if (t.texture <= 0 || t.texture >= 1) sec.fail("texture", "must be strictly inside (0, 1)");
		if (t.leg_width >= std::min(t.length, t.width))
			sec.fail("leg_width", "legs wider than the leg spacing would overlap");
		for (const auto& c : t.footprint().corners)
			if (c.x() < w.x_min || c.x() > w.x_max || c.y() < w.y_min || c.y() > w.y_max)
				sec.fail("", "table lies (partly) outside the arena");
		// Overlaps: footprints are compared only when their bounding boxes meet (fast on
		// worlds of thousands of tables).
		const auto foot = t.footprint();
		Box b{INFINITY, -INFINITY, INFINITY, -INFINITY};
		for (const auto& c : foot.corners)
			b.x0 = std::min(b.x0, c.x()), b.x1 = std::max(b.x1, c.x()), b.y0 = std::min(b.y0, c.y()), b.y1 = std::max(b.y1, c.y());
		for (size_t j = 0; j < w.tables.size(); j++)
			if (b.x0 <= boxes[j].x1 && boxes[j].x0 <= b.x1 && b.y0 <= boxes[j].y1 && boxes[j].y0 <= b.y1 &&
				foot.intersects(feet[j]))
				sec.fail("", "table overlaps [" + names[j] + "]");
		w.tables.push_back(t);
		names.push_back(name);
		feet.push_back(foot);
		boxes.push_back(b);
	}
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
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++)
			for (auto t : tables)
			{
				t.x += i * dx, t.y += j * dy;
				w.tables.push_back(t);
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
	return obs;
}
}  // namespace whiskermap::world
