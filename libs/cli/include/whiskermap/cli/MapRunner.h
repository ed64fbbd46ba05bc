#pragma once
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/obs/RawlogReader.h>

#include <functional>
#include <vector>

namespace whiskermap::cli
{
/** Feeds sweeps to a CMultiMetricMap holding a CHierarchicalObjectMap. In the per-pose mode
 *  it solves the sampler steps of a batch of sweeps on `jobs` threads (each with its own
 *  StepSolver) and integrates them in sweep order: the results are identical for any number
 *  of jobs. In the lasting mode each insertion depends on the previous ones: sweeps are
 *  inserted in order on the calling thread. Other maps of the multimap receive every sweep
 *  too, in order. */
class MapRunner
{
   public:
	/** Called after each sweep is integrated, in order. `ms`: the insertion's time (per-pose
	 *  mode: the step's solve + integrate time). */
	using OnStep = std::function<void(size_t index, const obs::RawlogReader::Sweep&, double ms)>;

	MapRunner(mrpt::maps::CMultiMetricMap& multimap, maps::CHierarchicalObjectMap& map, unsigned jobs, OnStep onStep);

	/** Queues a sweep; a full batch is processed at once. */
	void add(const obs::RawlogReader::Sweep& sweep);
	/** Processes what is queued. */
	void flush();
	/** Ask for a blackboard snapshot at schedule index `temperature` for sweep `index`. */
	void snapshot(size_t index, int temperature) { m_snapIndex = index, m_snapTemperature = temperature; }

   private:
	mrpt::maps::CMultiMetricMap& m_multimap;
	maps::CHierarchicalObjectMap& m_map;
	unsigned m_jobs;
	OnStep m_onStep;
	std::vector<maps::StepSolver> m_solvers;
	std::vector<obs::RawlogReader::Sweep> m_batch;
	size_t m_done = 0, m_snapIndex = SIZE_MAX;
	int m_snapTemperature = -1;
};
}  // namespace whiskermap::cli
