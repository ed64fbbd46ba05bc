#pragma once
#include <whiskermap/cli/Decimator.h>

#include <algorithm>
#include <cstddef>

namespace whiskermap::cli
{
/** whisker-slam's figures over its filter steps, in bounded memory: exact count, mean, max,
 *  least effective sample size and resamplings; step times and the ESS series as even
 *  subsets (every step while they fit: doc/slam.md, summary.json). */
struct StepFigures
{
	size_t count = 0, resamplings = 0;
	size_t pathPosesMax = 0;  ///< most path poses the filter held after a step (slam::PathTree::nodes)
	double totalMs = 0, maxMs = 0, minEss = 1;
	Decimator<double> ms{100000};  ///< step times, for the median and the 95th percentile
	Decimator<double> ess{10000};  ///< normalised ESS before resampling, every ess.stride()-th step

	void add(double stepMs, double stepEss, bool resampled, size_t pathPoses)
	{
		count++, resamplings += resampled, totalMs += stepMs, pathPosesMax = std::max(pathPosesMax, pathPoses);
		maxMs = std::max(maxMs, stepMs), minEss = std::min(minEss, stepEss);
		ms.add(stepMs), ess.add(stepEss);
	}
};
}  // namespace whiskermap::cli
