#pragma once
#include <whiskermap/cli/MapOutputs.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/cli/StepFigures.h>
#include <whiskermap/slam/RbpfSlam.h>
#include <whiskermap/slam/TSlamParams.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/world/Table.h>

#include <optional>
#include <string>
#include <vector>

namespace whiskermap::cli
{
/** whisker-slam's own outputs (doc/slam.md) besides the two path files the app streams
 *  (estimated_path.txt and odometry_path.txt, the ground-truth path columns, one line per
 *  sweep): paths.png (estimated, odometry and true paths over the map) and summary.json
 *  (particles, time per step, effective sample size over time, trajectory figures when the
 *  truth is known). Both read the path files back as streams, so memory does not grow with
 *  the log. The best particle's map goes through MapOutputs, whisker-map's writer. */
struct SlamOutputs
{
	static constexpr const char* ESTIMATED = "estimated_path.txt";
	static constexpr const char* ESTIMATED_TITLE =
		"whisker-slam: the estimated path (the best particle's, smoothed), one pose per sweep";
	static constexpr const char* FILTER = "filter_path.txt";
	static constexpr const char* FILTER_TITLE = "whisker-slam: the best particle's path, one pose per sweep";
	static constexpr const char* ODOMETRY = "odometry_path.txt";
	static constexpr const char* ODOMETRY_TITLE = "whisker-slam: the odometry of each sweep, as read from the rawlog";

	struct TRun
	{
		std::string input, config, mapConfig, truthPath;  ///< truthPath empty: no truth
		const slam::TSlamParams* params = nullptr;
		size_t sweeps = 0;  ///< lines in each path file (the truth file's first `sweeps` are scored)
		size_t particles = 0;  ///< the particles the filter ran (params->filterParticles())
		std::string estimatedFile, odometryFile;  ///< the path files, written (staged)
		std::string filterFile;  ///< the best particle's path, written (staged); empty: no filter (oracle)
		bool oracle = false;  ///< whisker-slam --oracle: no filter, the true path smoothed against the true solids
		StepFigures steps;
		std::vector<world::Table> mapTables;  ///< the map written: built at the estimated path (smoothed, or the best particle's)
		/** Without smoothing: the rebuilt map equals the best particle's map (with smoothing the
		 *  map is rebuilt at other poses: nothing to compare). */
		std::optional<bool> mapMatches;
		const smooth::PathSmoother::TResult* smoothing = nullptr;  ///< null: not smoothed
		double smoothingSeconds = 0;
		double wallSeconds = 0;
		/** The process's peak resident memory (MB) after the first tenth of the filter's steps
		 *  and after its last step, before the outputs are made: the filter's growth. */
		double filterRssTenthMb = 0, filterRssMb = 0;
		/** The heap in live use (MB, core::heapInUseMb: NaN if not measured) at the same two points. */
		double filterHeapTenthMb = 0, filterHeapMb = 0;
		/** What the particles' maps held at the same two points (slam::RbpfSlam::mapTotals). */
		slam::RbpfSlam::TMapTotals filterMapsTenth, filterMaps;
	};

	/** Writes paths.png and summary.json into `out`; returns a one-line result for the terminal. */
	static std::string write(OutputDir& out, const TRun& run, const MapOutputs::TSettings& picture);
};
}  // namespace whiskermap::cli
