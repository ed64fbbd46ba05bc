#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/EvalPaths.h>
#include <whiskermap/world/WorldGenerator.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <cstdio>

namespace whiskermap::world
{
namespace
{
/** One category's rules (doc/eval-worlds.md gives the reasons for each number). */
struct Spec
{
	const char* name;
	double arena;  ///< side of the square arena, metres
	int singles, pairs;  ///< free-standing tables, side-by-side pairs
	double minGap;  ///< smallest footprint gap between tables of different units, metres
	double closestAtMost;  ///< the closest gap must be at most this (clutter), metres
	int grid;  ///< n of the n x n paper grid; 0: sparse path
	int desks, chairs;  ///< free-standing desks and chairs (after the tables)
	int walls;  ///< random interior walls
	double wallMin, wallMax;  ///< every object's footprint gap to the nearest wall, metres
	double sizeJitter = 0;  ///< each object's length and width drawn within +- this of its class's, metres
	double legJitter = 0;  ///< each object's leg width drawn within +- this of its class's, metres
	double textureJitter = 0;  ///< each object's texture drawn within +- this of its class's
};
constexpr double WALL_MARGIN = 0.15;  ///< footprint to wall, metres
const Spec SPECS[] = {
	{"random_yaw", 4, 6, 0, 0.30, INFINITY, 10, 0, 0, 0, WALL_MARGIN, INFINITY},
	{"clutter", 4, 8, 0, 0.15, 0.25, 10, 0, 0, 0, WALL_MARGIN, INFINITY},
	{"side_by_side", 4, 2, 2, 0.30, INFINITY, 10, 0, 0, 0, WALL_MARGIN, INFINITY},
	{"large", 8, 24, 0, 0.30, INFINITY, 20, 0, 0, 0, WALL_MARGIN, INFINITY},
	{"sparse", 4, 6, 0, 0.30, INFINITY, 0, 0, 0, 0, WALL_MARGIN, INFINITY},
	// Issue 11: interior walls, object classes, objects close to walls.
	{"walls", 5, 6, 0, 0.30, INFINITY, 12, 0, 0, 3, WALL_MARGIN, INFINITY},
	{"mixed_classes", 5, 2, 0, 0.30, INFINITY, 12, 2, 4, 0, WALL_MARGIN, INFINITY},
	{"near_walls", 5, 2, 0, 0.30, INFINITY, 12, 2, 3, 2, 0.05, 0.25},
	// Issue 11: objects of their own sizes about their classes' (the catalogue's size_sigma, 2 cm)
	{"sized_classes", 5, 2, 0, 0.30, INFINITY, 12, 2, 4, 0, WALL_MARGIN, INFINITY, 0.03},
	// ... and with legs of their own: leg width within +-1 cm, texture within +-0.1 of the class's
	{"varied_legs", 5, 2, 0, 0.30, INFINITY, 12, 2, 4, 0, WALL_MARGIN, INFINITY, 0.03, 0.01, 0.1},
};
constexpr double WALL_THICKNESS = 0.1, WALL_GAP = 0.8;  ///< interior walls; smallest gap between two, metres
constexpr double FACING_MIN = 0.105, FACING_MAX = 0.195;  ///< facing leg centres of a pair, metres
constexpr int SPARSE_LEGS = 3, SPARSE_VISITS = 2;  ///< legs visited per table, visits per leg

/** To 1 mm: the nearest double to the decimal the .ini holds (k / 1000 is correctly rounded). */
double mm(double v)
{
	return std::round(v * 1000) / 1000;
}

/** An object of a class at a pose, snapped to 1 mm and 0.1 degree (the .ini holds exactly
 *  this): the paper's known table (1.0 x 0.6 m, 5 cm legs, texture 0.7), a desk (1.4 x 0.7 m,
 *  5 cm legs, 0.6) or a chair (0.42 m square, 3 cm legs, 0.5). */
Table object(const std::string& cls, double x, double y, double yawDeg)
{
	Table t;
	t.x = mm(x);
	t.y = mm(y);
	t.yaw = core::deg2rad(std::round(yawDeg * 10) / 10);
	t.object_class = ObjectClass(cls);
	if (cls == "desk") t.length = 1.4, t.width = 0.7, t.leg_width = 0.05, t.texture = 0.6;
	else if (cls == "chair") t.length = 0.42, t.width = 0.42, t.leg_width = 0.03, t.texture = 0.5;
	else t.length = 1.0, t.width = 0.6, t.leg_width = 0.05, t.texture = 0.7;
	return t;
}

Table knownTable(double x, double y, double yawDeg)
{
	return object("table", x, y, yawDeg);
}

/** A unit: one object, or two tables side by side (long sides facing, legs `facing` m apart). */
std::vector<Table> drawUnit(const World& w, bool pair, const std::string& cls, mrpt::random::CRandomGenerator& rng)
{
	const double x = rng.drawUniform(w.x_min + WALL_MARGIN, w.x_max - WALL_MARGIN);
	const double y = rng.drawUniform(w.y_min + WALL_MARGIN, w.y_max - WALL_MARGIN);
	const double yawDeg = rng.drawUniform(0.0, 180.0);
	if (!pair) return {object(cls, x, y, yawDeg)};
	const double facing = rng.drawUniform(FACING_MIN, FACING_MAX);
	const Eigen::Vector2d half = Eigen::Rotation2Dd(core::deg2rad(yawDeg)) * Eigen::Vector2d(0, (0.6 + facing) / 2);
	return {knownTable(x - half.x(), y - half.y(), yawDeg), knownTable(x + half.x(), y + half.y(), yawDeg)};
}

/** Smallest gap from a footprint to the arena's and the interior walls. */
double wallGap(const World& w, const Obstacle& foot)
{
	double g = INFINITY;
	for (const auto& c : foot.corners)
		g = std::min({g, c.x() - w.x_min, w.x_max - c.x(), c.y() - w.y_min, w.y_max - c.y()});
	for (const auto& v : w.walls) g = std::min(g, foot.gap(v.slab()));
	return g;
}

bool fits(const World& w, const std::vector<Table>& unit, const Spec& spec)
{
	for (const auto& t : unit)
	{
		for (const auto& c : t.footprint().corners)
			if (c.x() < w.x_min + spec.wallMin || c.x() > w.x_max - spec.wallMin || c.y() < w.y_min + spec.wallMin ||
				c.y() > w.y_max - spec.wallMin)
				return false;
		for (const auto& o : w.tables)
			if (t.footprint().gap(o.footprint()) < spec.minGap) return false;
		if (w.walls.empty() && std::isinf(spec.wallMax)) continue;
		const double g = wallGap(w, t.footprint());
		if (g < spec.wallMin || g > spec.wallMax) return false;
	}
	return true;
}

/** A random straight wall (0.1 m thick, texture 0.3, 1 to 2.5 m long, along x or y), ends on
 *  a 1 mm grid inside the arena; at least WALL_GAP from the walls already placed. */
bool drawWall(World& w, mrpt::random::CRandomGenerator& rng)
{
	const bool alongX = rng.drawUniform(0.0, 1.0) < 0.5;
	const double len = rng.drawUniform(1.0, 2.5);
	const double cx = rng.drawUniform(w.x_min, w.x_max), cy = rng.drawUniform(w.y_min, w.y_max);
	Wall v;
	v.x0 = mm(alongX ? cx - len / 2 : cx), v.x1 = mm(alongX ? cx + len / 2 : cx);
	v.y0 = mm(alongX ? cy : cy - len / 2), v.y1 = mm(alongX ? cy : cy + len / 2);
	v.thickness = WALL_THICKNESS, v.texture = w.wall_texture;
	if (std::min({v.x0, v.x1}) < w.x_min || std::max({v.x0, v.x1}) > w.x_max || std::min({v.y0, v.y1}) < w.y_min ||
		std::max({v.y0, v.y1}) > w.y_max)
		return false;
	for (const auto& o : w.walls)
		if (v.slab().gap(o.slab()) < WALL_GAP) return false;
	w.walls.push_back(v);
	return true;
}

/** Places every unit of `spec` (each up to 1000 draws); nothing if one does not fit. */
std::optional<World> layout(const Spec& spec, mrpt::random::CRandomGenerator& rng)
{
	World w;
	w.x_max = w.y_max = spec.arena;
	for (int k = 0; k < spec.walls; k++)
	{
		bool placed = false;
		for (int tries = 0; tries < 1000 && !placed; tries++) placed = drawWall(w, rng);
		if (!placed) return std::nullopt;
	}
	const int tables = spec.pairs + spec.singles;
	for (int u = 0; u < tables + spec.desks + spec.chairs; u++)
	{
		const std::string cls = u < tables ? "table" : u < tables + spec.desks ? "desk" : "chair";
		bool placed = false;
		for (int tries = 0; tries < 1000 && !placed; tries++)
		{
			auto unit = drawUnit(w, u < spec.pairs, cls, rng);
			if (spec.sizeJitter > 0)  // other categories draw exactly as before
				for (auto& t : unit)
				{
					t.length = mm(t.length + rng.drawUniform(-spec.sizeJitter, spec.sizeJitter));
					t.width = mm(t.width + rng.drawUniform(-spec.sizeJitter, spec.sizeJitter));
					if (spec.legJitter == 0) continue;  // sized_classes draws exactly as before
					t.leg_width = mm(t.leg_width + rng.drawUniform(-spec.legJitter, spec.legJitter));
					t.texture = mm(t.texture + rng.drawUniform(-spec.textureJitter, spec.textureJitter));
				}
			if ((placed = fits(w, unit, spec))) w.tables.insert(w.tables.end(), unit.begin(), unit.end());
		}
		if (!placed) return std::nullopt;
	}
	return w;
}

double closestGap(const World& w)
{
	double g = INFINITY;
	for (size_t i = 0; i < w.tables.size(); i++)
		for (size_t j = i + 1; j < w.tables.size(); j++)
			g = std::min(g, w.tables[i].footprint().gap(w.tables[j].footprint()));
	return g;
}
}  // namespace

const std::vector<std::string>& WorldGenerator::categories()
{
	static const std::vector<std::string> names = [] {
		std::vector<std::string> v;
		for (const auto& s : SPECS) v.push_back(s.name);
		return v;
	}();
	return names;
}

WorldGenerator::Scenario WorldGenerator::generate(const std::string& category, uint64_t seed) const
{
	const auto& names = categories();
	const auto it = std::find(names.begin(), names.end(), category);
	if (it == names.end()) throw core::Error("unknown world category '" + category + "'");
	const Spec& spec = SPECS[it - names.begin()];
	// One stream per (category, seed): categories with the same seed differ.
	mrpt::random::CRandomGenerator rng(static_cast<uint32_t>(seed * 2654435761u + (it - names.begin()) * 40503u + 1));

	for (int attempt = 1; attempt <= m_s.maxAttempts; attempt++)
	{
		auto w = layout(spec, rng);
		if (!w || closestGap(*w) > spec.closestAtMost) continue;
		Scenario s;
		s.category = category, s.seed = seed, s.attempt = attempt, s.world = *w;
		s.closestGap = closestGap(*w);
		if (spec.grid > 0)
		{
			s.path = EvalPaths::freeGrid(*w, m_s.robot, spec.grid, &s.droppedPoses);
			if (!EvalPaths::gridConnected(*w, m_s.robot, spec.grid)) continue;
		}
		else
		{
			auto path = EvalPaths::sparse(*w, m_s.robot, m_s.window, SPARSE_LEGS, SPARSE_VISITS, rng);
			if (!path) continue;
			s.path = std::move(*path);
		}
		// Verified at every noise level (the truth does not depend on the noise, but this is
		// what whisker-sim will record, so check what it will record).
		bool ok = true;
		for (const auto& noise : m_s.noises)
		{
			const auto a = TouchAudit::run(*w, m_s.robot, noise, m_s.simSeed, s.path);
			ok = ok && a.blockedPoses == 0 && a.fewestLegs() >= 2 &&
				 (spec.grid > 0 || a.closestCrossLegSpacing() >= m_s.window);
			s.audit = a;
		}
		if (!ok) continue;
		s.verified = "paths checked with the simulator at " + std::to_string(m_s.noises.size()) +
					 " noise level(s), whisker-sim --seed " + std::to_string(m_s.simSeed) +
					 "; working memory " + std::to_string(m_s.window) + " contacts";
		return s;
	}
	throw core::Error(
		category + " seed " + std::to_string(seed) + ": no layout accepted in " + std::to_string(m_s.maxAttempts) +
		" attempts");
}

std::string WorldGenerator::Scenario::description() const
{
	char buf[512];
	std::string s;
	const bool onlyTables = world.walls.empty() &&
		std::all_of(world.tables.begin(), world.tables.end(), [](const Table& t) { return t.object_class == ObjectClass(); });
	std::snprintf(
		buf, sizeof(buf),
		"whisker-worldgen --category %s --seed %llu (layout %d); doc/eval-worlds.md\n"
		"arena %g x %g m, %zu %s, closest footprint gap %.3f m\n"
		"path: %zu poses (%zu blocked grid poses dropped), %zu contacts, %zu on table legs\n"
		"identifiable tables (simulator truth: touched on >= 2 legs): %zu of %zu; legs touched per table:",
		category.c_str(), static_cast<unsigned long long>(seed), attempt, world.x_max - world.x_min,
		world.y_max - world.y_min, world.tables.size(),
		onlyTables ? "tables (1.0 x 0.6 m, 5 cm legs, texture 0.7; walls 0.3)" : "objects (classes and walls below)", closestGap,
		path.size(), droppedPoses,
		audit.contacts.size(), audit.tableContacts(), audit.identifiable(), world.tables.size());
	s += buf;
	for (const auto& b : audit.legsTouched) s += " " + std::to_string(b.count());
	// Side-by-side pairs: two legs of one table within 25 cm of two legs of another.
	std::string pairs;
	for (size_t i = 0; i < world.tables.size(); i++)
		for (size_t j = i + 1; j < world.tables.size(); j++)
		{
			int facing = 0;
			double closest = INFINITY;
			for (int a = 0; a < 4; a++)
				for (int b = 0; b < 4; b++)
				{
					const double d = (world.tables[i].legCentre(a) - world.tables[j].legCentre(b)).norm();
					facing += d <= 0.25;
					closest = std::min(closest, d);
				}
			if (facing != 2) continue;
			std::snprintf(buf, sizeof(buf), "%s tables %zu+%zu %.3f m", pairs.empty() ? "" : ",", i, j, closest);
			pairs += buf;
		}
	if (!pairs.empty()) s += "\nside-by-side pairs, facing leg centres apart:" + pairs;
	const size_t spacing = audit.closestCrossLegSpacing();
	s += "\nclosest contacts on two legs of one table: " +
		 (spacing == SIZE_MAX ? std::string("never") : std::to_string(spacing) + " contacts apart") + "\n";
	// Issue 11's categories: classes and interior walls (absent from the older ones' text).
	if (onlyTables) return s + verified + "\n";
	size_t desks = 0, chairs = 0;
	double toWall = INFINITY;
	for (const auto& t : world.tables)
	{
		desks += t.object_class.str() == "desk", chairs += t.object_class.str() == "chair";
		toWall = std::min(toWall, wallGap(world, t.footprint()));
	}
	std::snprintf(
		buf, sizeof(buf),
		"objects: %zu tables (1.0 x 0.6 m, 5 cm legs, texture 0.7), %zu desks (1.4 x 0.7 m, 5 cm legs, 0.6), %zu chairs "
		"(0.42 m square, 3 cm legs, 0.5); %zu interior walls (0.1 m thick, texture 0.3; arena walls 0.3); closest "
		"footprint to a wall %.3f m\n",
		world.tables.size() - desks - chairs, desks, chairs, world.walls.size(), toWall);
	return s + buf + verified + "\n";
}
}  // namespace whiskermap::world
