#include <whiskermap/cli/MapRunner.h>

#include <chrono>
#include <thread>

namespace whiskermap::cli
{
namespace
{
double msSince(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

MapRunner::MapRunner(
	mrpt::maps::CMultiMetricMap& multimap, maps::CHierarchicalObjectMap& map, unsigned jobs, OnStep onStep)
	: m_multimap(multimap), m_map(map), m_jobs(std::max(1u, jobs)), m_onStep(std::move(onStep)), m_solvers(m_jobs)
{
}

void MapRunner::add(const obs::RawlogReader::Sweep& sweep)
{
	m_batch.push_back(sweep);
	if (m_batch.size() >= 64 * m_jobs) flush();
}

void MapRunner::flush()
{
	const size_t n = m_batch.size();
	if (m_map.lasting())
	{
		// Each insertion builds on the map the previous ones left: in order, on this thread.
		for (size_t i = 0; i < n; i++)
		{
			const auto t0 = std::chrono::steady_clock::now();
			const mrpt::poses::CPose3D pose(m_batch[i].robotPose);
			m_map.insertObservation(*m_batch[i].obs, pose);
			const double ms = msSince(t0);
			for (auto& other : m_multimap.maps)
				if (other.get() != &m_map) other->insertObservation(*m_batch[i].obs, pose);
			m_onStep(m_done + i, m_batch[i], ms);
		}
		m_done += n;
		m_batch.clear();
		return;
	}
	// Inputs in order (the working memory slides sweep by sweep) ...
	std::vector<maps::TStepInput> inputs;
	inputs.reserve(n);
	for (const auto& s : m_batch) inputs.push_back(m_map.prepareStep(*s.obs, s.robotPose));
	// ... steps solved independently, thread t taking steps t, t + jobs, ...
	std::vector<inference::StepResult> results(n);
	std::vector<double> ms(n);
	auto work = [&](unsigned t) {
		for (size_t i = t; i < n; i += m_jobs)
		{
			const auto t0 = std::chrono::steady_clock::now();
			const int snap = m_done + i == m_snapIndex ? m_snapTemperature : -1;
			results[i] = m_solvers[t].solve(inputs[i], m_map.samplerParams, snap);
			ms[i] = msSince(t0);
		}
	};
	std::vector<std::thread> threads;
	for (unsigned t = 1; t < m_jobs && t < n; t++) threads.emplace_back(work, t);
	work(0);
	for (auto& th : threads) th.join();
	// ... and integrated in order.
	for (size_t i = 0; i < n; i++)
	{
		const auto t0 = std::chrono::steady_clock::now();
		m_map.integrateStep(std::move(inputs[i]), std::move(results[i]));
		const mrpt::poses::CPose3D pose(m_batch[i].robotPose);
		for (auto& other : m_multimap.maps)
			if (other.get() != &m_map) other->insertObservation(*m_batch[i].obs, pose);
		m_onStep(m_done + i, m_batch[i], ms[i] + msSince(t0));
	}
	m_done += n;
	m_batch.clear();
}
}  // namespace whiskermap::cli
