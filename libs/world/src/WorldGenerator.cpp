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
};
const Spec SPECS[] = {
	{"random_yaw", 4, 6, 0, 0.30, INFINITY, 10},
	{"clutter", 4, 8, 0, 0.15, 0.25, 10},
	{"side_by_side", 4, 2, 2, 0.30, INFINITY, 10},
	{"large", 8, 24, 0, 0.30, INFINITY, 20},
	{"sparse", 4, 6, 0, 0.30, INFINITY, 0},
};
constexpr double WALL_MARGIN = 0.15;  ///< footprint to wall, metres
constexpr double FACING_MIN = 0.105, FACING_MAX = 0.195;  ///< facing leg centres of a pair, metres
constexpr int SPARSE_LEGS = 3, SPARSE_VISITS = 2;  ///< legs visited per table, visits per leg

/** The paper's known table, snapped to 1 mm and 0.1 degree (the .ini holds exactly this). */
Table knownTable(double x, double y, double yawDeg)
{
	Table t;
	t.x = std::round(x * 1000) / 1000;
	t.y = std::round(y * 1000) / 1000;
	t.yaw = core::deg2rad(std::round(yawDeg * 10) / 10);
	t.length = 1.0, t.width = 0.6, t.leg_width = 0.05, t.texture = 0.7;
	return t;
}

/** A unit: one table, or two side by side (long sides facing, legs `facing` m apart). */
std::vector<Table> drawUnit(const World& w, bool pair, mrpt::random::CRandomGenerator& rng)
{
	const double x = rng.drawUniform(w.x_min + WALL_MARGIN, w.x_max - WALL_MARGIN);
	const double y = rng.drawUniform(w.y_min + WALL_MARGIN, w.y_max - WALL_MARGIN);
	const double yawDeg = rng.drawUniform(0.0, 180.0);
	if (!pair) return {knownTable(x, y, yawDeg)};
	const double facing = rng.drawUniform(FACING_MIN, FACING_MAX);
	const Eigen::Vector2d half = Eigen::Rotation2Dd(core::deg2rad(yawDeg)) * Eigen::Vector2d(0, (0.6 + facing) / 2);
	return {knownTable(x - half.x(), y - half.y(), yawDeg), knownTable(x + half.x(), y + half.y(), yawDeg)};
}

bool fits(const World& w, const std::vector<Table>& unit, double minGap)
{
	for (const auto& t : unit)
	{
		for (const auto& c : t.footprint().corners)
			if (c.x() < w.x_min + WALL_MARGIN || c.x() > w.x_max - WALL_MARGIN || c.y() < w.y_min + WALL_MARGIN ||
				c.y() > w.y_max - WALL_MARGIN)
				return false;
		for (const auto& o : w.tables)
			if (t.footprint().gap(o.footprint()) < minGap) return false;
	}
	return true;
}

/** Places every unit of `spec` (each up to 1000 draws); nothing if one does not fit. */
std::optional<World> layout(const Spec& spec, mrpt::random::CRandomGenerator& rng)
{
	World w;
	w.x_max = w.y_max = spec.arena;
	for (int u = 0; u < spec.pairs + spec.singles; u++)
	{
		bool placed = false;
		for (int tries = 0; tries < 1000 && !placed; tries++)
		{
			const auto unit = drawUnit(w, u < spec.pairs, rng);
			if ((placed = fits(w, unit, spec.minGap))) w.tables.insert(w.tables.end(), unit.begin(), unit.end());
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
	std::snprintf(
		buf, sizeof(buf),
		"whisker-worldgen --category %s --seed %llu (layout %d); doc/eval-worlds.md\n"
		"arena %g x %g m, %zu tables (1.0 x 0.6 m, 5 cm legs, texture 0.7; walls 0.3), closest footprint gap %.3f m\n"
		"path: %zu poses (%zu blocked grid poses dropped), %zu contacts, %zu on table legs\n"
		"identifiable tables (simulator truth: touched on >= 2 legs): %zu of %zu; legs touched per table:",
		category.c_str(), static_cast<unsigned long long>(seed), attempt, world.x_max - world.x_min,
		world.y_max - world.y_min, world.tables.size(), closestGap, path.size(), droppedPoses,
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
	return s + verified + "\n";
}
}  // namespace whiskermap::world
