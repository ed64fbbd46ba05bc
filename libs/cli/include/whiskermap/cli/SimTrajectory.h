#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/TrajectoryGenerator.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <memory>
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
		std::unique_ptr<world::PoseSource> source;  ///< one pose at a time (bounded memory)
		double rate = 1;  ///< sweeps per second
		bool skipBlocked = false;  ///< paper-grid: blocked positions are left out, by design
	};
	/** The poses to simulate in `sim`'s world (already tiled `tilesX` x `tilesY`). A blocked
	 *  pose in a --path file is a core::Error naming the file and line (the whole file is
	 *  checked here); blocked paper-grid poses are for the caller to skip (skipBlocked). An
	 *  option given for another kind of trajectory (--speed with paper-grid, --grid with
	 *  lawnmower, ...) is an error. */
	Poses poses(const world::WhiskerSimulator& sim, int tilesX, int tilesY, uint64_t seed) const;

   private:
	std::vector<const CLI::Option*> m_continuousOnly;  ///< given: the trajectory must be continuous
	const CLI::Option* m_grid = nullptr;
};
}  // namespace whiskermap::cli
