#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/world/Table.h>

#include <cstdint>
#include <vector>

namespace whiskermap::maps
{
/** What one inserted sweep concluded: the MAP set of tables of that time step (eq. 18), as
 *  the paper collates them over poses (its figs. 5-7). */
struct TPoseRecord
{
	mrpt::poses::CPose2D pose;  ///< robot pose of the sweep
	std::vector<world::Table> tables;  ///< MAP tables (known size filled in)
	double logPosterior = 0;  ///< log joint (eq. 14) of the MAP blackboard
	uint32_t shapelets = 0;  ///< shapelets in working memory for this step
};
}  // namespace whiskermap::maps
