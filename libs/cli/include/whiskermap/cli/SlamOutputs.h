#pragma once
#include <whiskermap/cli/MapOutputs.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/slam/RbpfSlam.h>
#include <whiskermap/world/PathLog.h>

#include <optional>
#include <string>
#include <vector>

namespace whiskermap::cli
{
/** whisker-slam's own outputs (doc/slam.md): estimated_path.txt and odometry_path.txt (the
 *  ground-truth path columns, one line per sweep), paths.png (estimated, odometry and true
 *  paths over the map) and summary.json (particles, time per step, effective sample size
 *  over time, trajectory figures when the truth is known). The best particle's map goes
 *  through MapOutputs, whisker-map's writer. */
struct SlamOutputs
{
	struct TRun
	{
		std::string input, config, mapConfig, truthPath;
		const slam::TSlamParams* params = nullptr;
		const slam::RbpfSlam* slam = nullptr;
		std::vector<world::PathLog::Entry> odometry, estimated;  ///< one per sweep
		std::optional<std::vector<world::PathLog::Entry>> truth;  ///< same length, if known
		std::vector<world::Table> mapTables;  ///< the best particle's map
		bool mapMatches = false;  ///< the rebuilt map equals the best particle's map
		double wallSeconds = 0;
	};

	/** Writes the files into `out`; returns a one-line result for the terminal. */
	static std::string write(OutputDir& out, const TRun& run, const MapOutputs::TSettings& picture);
};
}  // namespace whiskermap::cli
