#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/obs/Shapelet.h>
#include <whiskermap/obs/SweptSector.h>

#include <cstdint>
#include <vector>

namespace whiskermap::maps
{
/** Everything one time step of the sampler needs, fixed when its sweep is inserted: steps
 *  can then be solved in any order, or in parallel, with the same results. */
struct TStepInput
{
	mrpt::poses::CPose2D pose;  ///< robot pose of the sweep
	std::vector<obs::Shapelet> shapelets;  ///< the sweep's own contacts
	std::vector<obs::Shapelet> memory;  ///< working memory: the data of the step
	std::vector<obs::SweptSector> swept;  ///< its sweeps' free space (model free_space on, eq. 21)
	uint64_t seed = 0;  ///< the step's seed
	model::ModelParams model;  ///< the model the step is scored with
};
}  // namespace whiskermap::maps
