#pragma once
#include <whiskermap/world/Obstacle.h>
#include <whiskermap/world/Table.h>

#include <string>
#include <vector>

namespace whiskermap::render
{
/** Exports tables as an OctoMap occupancy octree (`.bt`, OctoMap's binary format, read by
 *  octovis, convert_octree and any OctoMap user): each leg a square column from the floor to
 *  `height`, the top a slab of `topThickness` just below `height` over the whole footprint.
 *  Voxels (edge `resolution`) whose centres lie inside a solid are occupied; nothing else
 *  is stored (unknown space stays unknown). */
struct OcTreeExport
{
	struct TOptions
	{
		double resolution = 0.02;  ///< voxel edge, metres
		double height = 0.7;  ///< table height (top surface), metres
		double topThickness = 0.03;  ///< metres
	};

	/** OctoMap's 16-bit keys span +-range(resolution) metres around the origin. */
	static double range(double resolution);

	/** Writes via a temporary file; returns the number of occupied voxels inserted.
	 *  Throws core::Error if the file cannot be written or a table lies beyond range(). */
	static size_t write(const std::vector<world::Table>& tables, const TOptions& o, const std::string& path);
	/** The same plus walls: each a solid column over its footprint from the floor to `height`. */
	static size_t write(
		const std::vector<world::Table>& tables, const std::vector<world::Obstacle>& walls, const TOptions& o,
		const std::string& path);
};
}  // namespace whiskermap::render
