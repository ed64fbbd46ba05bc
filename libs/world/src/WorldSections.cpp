#include "WorldSections.h"

#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace whiskermap::world::detail
{
namespace
{
const double BIG = 1e4;

/** Sections named prefix + N, in order of N; an ill-formed N is an error. */
std::vector<std::string> indexedSections(
	const core::IniFile& cfg, const std::string& prefix, long limit)
{
	std::map<long, std::string> byIndex;
	for (const auto& s : cfg.sectionsInOrder())
	{
		if (s.rfind(prefix, 0) != 0) continue;
		const long n = core::sectionIndex(s, prefix, limit);
		if (n < 0)
			throw core::Error(
				core::iniWhere(cfg, s) + "[" + s + "]: " + prefix.substr(0, prefix.size() - 1) +
				" sections must be named " + prefix + "N, N = 0, 1, ... (no leading zeros, N < " +
				std::to_string(limit) + ")");
		byIndex[n] = s;
	}
	std::vector<std::string> names;
	for (const auto& [index, name] : byIndex) names.push_back(name);
	return names;
}

bool insideArena(const World& w, double x, double y)
{
	return x >= w.x_min && x <= w.x_max && y >= w.y_min && y <= w.y_max;
}

ObjectClass readClass(core::IniSection& sec)
{
	const std::string c = sec.text("class", "table");
	if (!ObjectClass::valid(c)) sec.fail("class", "'" + c + "' is not a class name (1 to 31 letters, digits or _)");
	return ObjectClass(c);
}

struct Box
{
	double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
	explicit Box(const Obstacle& o)
	{
		for (const auto& c : o.corners)
			x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x()), y0 = std::min(y0, c.y()), y1 = std::max(y1, c.y());
	}
	bool meets(const Box& b) const { return x0 <= b.x1 && b.x0 <= x1 && y0 <= b.y1 && b.y0 <= y1; }
};
}  // namespace

std::vector<std::string> readWalls(const core::IniFile& cfg, const std::string& path, World& w)
{
	const auto names = indexedSections(cfg, "wall_", World::MAX_WALLS);
	const double span = std::max(w.x_max - w.x_min, w.y_max - w.y_min);
	for (const auto& name : names)
	{
		core::IniSection sec(cfg, name, path);
		Wall wall;
		wall.x0 = sec.number("x0", -BIG, BIG);
		wall.y0 = sec.number("y0", -BIG, BIG);
		wall.x1 = sec.number("x1", -BIG, BIG);
		wall.y1 = sec.number("y1", -BIG, BIG);
		wall.thickness = sec.number("thickness", 1e-3, 2);
		wall.texture = sec.number("texture", 0, 1);
		sec.finish();
		if (!insideArena(w, wall.x0, wall.y0) || !insideArena(w, wall.x1, wall.y1))
			sec.fail("", "wall end point outside the arena");
		if (wall.length() < 1e-3) sec.fail("", "wall has zero length (its end points coincide)");
		if (wall.thickness > 0.5 * span) sec.fail("thickness", "wall thicker than half the arena");
		w.walls.push_back(wall);
	}
	return names;
}

void readTables(
	const core::IniFile& cfg, const std::string& path, const std::vector<std::string>& wallNames,
	World& w)
{
	std::vector<std::string> names;
	std::vector<Obstacle> feet;
	std::vector<Box> boxes;
	std::vector<Obstacle> slabs;
	for (const auto& wall : w.walls) slabs.push_back(wall.slab());
	for (const auto& name : indexedSections(cfg, "table_", World::MAX_TABLES))
	{
		core::IniSection sec(cfg, name, path);
		Table t;
		t.object_class = readClass(sec);
		t.x = sec.number("x", -BIG, BIG);
		t.y = sec.number("y", -BIG, BIG);
		t.yaw = core::deg2rad(sec.number("yaw_deg", -360, 360));
		t.length = sec.number("length", 1e-3, 100);
		t.width = sec.number("width", 1e-3, 100);
		t.leg_width = sec.number("leg_width", 1e-3, 10);
		t.texture = sec.number("texture", 0, 1);
		sec.finish();
		if (t.texture <= 0 || t.texture >= 1) sec.fail("texture", "must be strictly inside (0, 1)");
		if (t.leg_width >= std::min(t.length, t.width))
			sec.fail("leg_width", "legs wider than the leg spacing would overlap");
		const auto foot = t.footprint();
		for (const auto& c : foot.corners)
			if (!insideArena(w, c.x(), c.y())) sec.fail("", "table lies (partly) outside the arena");
		for (size_t j = 0; j < slabs.size(); j++)
			if (foot.intersects(slabs[j])) sec.fail("", "object overlaps [" + wallNames[j] + "]");
		// Overlaps: footprints are compared only when their bounding boxes meet (fast on
		// worlds of thousands of tables).
		const Box b(foot);
		for (size_t j = 0; j < w.tables.size(); j++)
			if (b.meets(boxes[j]) && foot.intersects(feet[j])) sec.fail("", "table overlaps [" + names[j] + "]");
		w.tables.push_back(t);
		names.push_back(name);
		feet.push_back(foot);
		boxes.push_back(b);
	}
}
}  // namespace whiskermap::world::detail
