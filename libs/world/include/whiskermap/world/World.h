#pragma once
#include <whiskermap/world/Obstacle.h>
#include <whiskermap/world/Table.h>
#include <whiskermap/world/Wall.h>

#include <string>
#include <vector>

namespace whiskermap::world
{
/** The arena (a rectangle walled on its four edges), its interior walls and its four-legged
 *  objects (tables, desks, chairs: the `tables`): the ground truth a simulator senses and an
 *  evaluation compares against. See doc/formats.md for the .ini. */
struct World
{
	/** Most tables a world file may hold ([table_0] .. [table_99999]). */
	static constexpr long MAX_TABLES = 100000;
	/** Most interior walls a world file may hold ([wall_0] .. [wall_9999]). */
	static constexpr long MAX_WALLS = 10000;

	double x_min = 0, x_max = 0, y_min = 0, y_max = 0;  ///< walls stand on these edges, metres
	double wall_texture = 0.3;  ///< texture of the walls (optional key in [arena])
	std::vector<Table> tables;
	std::vector<Wall> walls;  ///< interior walls

	/** Reads and validates a world .ini. Unknown sections or keys, missing keys, bad values,
	 *  tables outside the arena or overlapping each other or a wall, walls of zero length or
	 *  leaving the arena are core::Error naming file, section and key. */
	static World load(const std::string& path);
	/** Writes the world in the same .ini format (it loads back to the same values); each
	 *  line of `comment`, if any, becomes a `; ` comment line under the header. */
	void save(const std::string& path, const std::string& comment = "") const;

	/** This world repeated nx times along x and ny times along y (same table density): the
	 *  scaling benchmarks' worlds of 6, 60 and 600 tables. */
	World tiled(int nx, int ny) const;

	/** All legs (tagged with their table and leg index), four wall slabs of the given
	 *  thickness just outside the arena, then the interior walls' slabs (table -1). */
	std::vector<Obstacle> obstacles(double wallThickness = 1.0) const;
};
}  // namespace whiskermap::world
