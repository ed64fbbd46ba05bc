#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/world/TrajectoryGenerator.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <string>
#include <vector>

namespace CLI
{
class App;
class Option;
}

namespace whiskermap::cli
{
/** whisker-sim's trajectory options (--trajectory, --path, --grid, --speed, --rate, ...) and
 *  the poses they give. */
struct SimTrajectory
{
	std::string kind = "paper-grid", path;
	int grid = 10;
	double rate = 0;  ///< sweeps per second; 0: 1 for paper-grid and --path, spec.rate otherwise
	world::TrajectorySpec spec;

	void add(CLI::App& app);

	struct Poses
	{
		std::vector<mrpt::poses::CPose2D> poses;
		double rate = 1;  ///< sweeps per second
		size_t skipped = 0;  ///< blocked paper-grid positions left out
	};
	/** The poses to simulate in `sim`'s world (already tiled `tilesX` x `tilesY`). A blocked
	 *  pose in a --path file is a core::Error naming the file and line; blocked paper-grid
	 *  poses are skipped (reported on stderr unless `quiet`). An option given for another
	 *  kind of trajectory (--speed with paper-grid, --grid with lawnmower, ...) is an error. */
	Poses poses(const world::WhiskerSimulator& sim, int tilesX, int tilesY, uint64_t seed, bool quiet) const;

   private:
	std::vector<const CLI::Option*> m_continuousOnly;  ///< given: the trajectory must be continuous
	const CLI::Option* m_grid = nullptr;
};
}  // namespace whiskermap::cli
