#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/world/World.h>

#include <string>
#include <vector>

namespace whiskermap::world
{
/** Robot poses to simulate. */
struct Trajectory
{
	/** The paper's grid: n x n positions at the centres of an n x n division of the arena,
	 *  row by row from (x_min, y_min), each visited at the four compass headings
	 *  0, 90, 180, 270 degrees: 4 n^2 poses. */
	static std::vector<mrpt::poses::CPose2D> paperGrid(const World& world, int n = 10);
	/** The same with nx x ny positions (for non-square, e.g. tiled, arenas). */
	static std::vector<mrpt::poses::CPose2D> paperGrid(const World& world, int nx, int ny);

	/** A path file: one pose per line, `x y yaw_deg` (metres, degrees); blank lines and lines
	 *  starting with '%' or '#' are skipped. Throws core::Error naming file and line.
	 *  `lines` (optional) receives each pose's line number, for later errors. */
	static std::vector<mrpt::poses::CPose2D> readPathFile(
		const std::string& path, std::vector<int>* lines = nullptr);
	/** Writes a path file that readPathFile reads back to the same poses (to 1e-9 m and
	 *  degrees); each line of `comment` becomes a `# ` line at the top. Throws core::Error. */
	static void writePathFile(
		const std::string& path, const std::vector<mrpt::poses::CPose2D>& poses,
		const std::string& comment = "");
};
}  // namespace whiskermap::world
