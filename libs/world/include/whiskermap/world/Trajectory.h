#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/world/World.h>

#include <memory>
#include <string>
#include <vector>

namespace whiskermap::world
{
/** Robot poses produced one at a time, so a trajectory of any length takes bounded memory. */
class PoseSource
{
   public:
	virtual ~PoseSource() = default;
	/** The next pose; false after the last (then rewind() starts over). */
	virtual bool next(mrpt::poses::CPose2D& pose) = 0;
	virtual void rewind() = 0;
	/** How many poses one pass gives. */
	virtual size_t size() const = 0;
	/** Where the pose last returned came from, for errors ("FILE: line N: "; "" if nowhere). */
	virtual std::string where() const { return ""; }
};

/** Robot poses to simulate. */
struct Trajectory
{
	/** Positions beyond this (metres, |x| and |y|) are refused, as by the rawlog reader. */
	static constexpr double MAX_COORDINATE = 1e5;

	/** The paper's grid: n x n positions at the centres of an n x n division of the arena,
	 *  row by row from (x_min, y_min), each visited at the four compass headings
	 *  0, 90, 180, 270 degrees: 4 n^2 poses. */
	static std::vector<mrpt::poses::CPose2D> paperGrid(const World& world, int n = 10);
	/** The same with nx x ny positions (for non-square, e.g. tiled, arenas). */
	static std::vector<mrpt::poses::CPose2D> paperGrid(const World& world, int nx, int ny);
	/** The grid, one pose at a time. */
	static std::unique_ptr<PoseSource> paperGridSource(const World& world, int nx, int ny);

	/** A path file: one pose per line, `x y yaw_deg` (metres, degrees); blank lines and lines
	 *  starting with '%' or '#' are skipped. Lines of at most 4096 bytes, no control bytes,
	 *  |x|, |y| <= MAX_COORDINATE, |yaw_deg| <= 3600. The whole file is checked when the
	 *  source is made; errors are core::Error naming file and line. */
	static std::unique_ptr<PoseSource> pathFileSource(const std::string& path);
	/** All poses of a path file (memory grows with the file: tests and short paths).
	 *  `lines` (optional) receives each pose's line number, for later errors. */
	static std::vector<mrpt::poses::CPose2D> readPathFile(
		const std::string& path, std::vector<size_t>* lines = nullptr);
	/** The given poses, one at a time (generated trajectories). */
	static std::unique_ptr<PoseSource> vectorSource(std::vector<mrpt::poses::CPose2D> poses);
	/** Writes a path file that readPathFile reads back to the same poses (to 1e-9 m and
	 *  degrees); each line of `comment` becomes a `# ` line at the top. Throws core::Error. */
	static void writePathFile(
		const std::string& path, const std::vector<mrpt::poses::CPose2D>& poses,
		const std::string& comment = "");
};
}  // namespace whiskermap::world
