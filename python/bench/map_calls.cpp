// map_calls RAWLOG MODE REPEATS: the C++ half of scripts/bench-python.sh (map_calls.py is the
// Python half, with the same loops and line format).
// - insertion: every sweep of the rawlog into a fresh map (shipped config, keep_history off as
//   in whisker-map), REPEATS times; best and median microseconds per sweep of process CPU time
//   (steadier than wall time on a shared machine) and the best of wall time;
// - likelihood: against the last map, each sweep at 64 poses around its own (a particle
//   filter's weights), microseconds per call of CPU time.
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

using namespace whiskermap;

namespace
{
double cpuUs(std::clock_t c0) { return 1e6 * double(std::clock() - c0) / CLOCKS_PER_SEC; }
}  // namespace

int main(int argc, char** argv)
{
	if (argc != 4)
	{
		std::fprintf(stderr, "usage: map_calls RAWLOG lasting|per_pose REPEATS\n");
		return 1;
	}
	const std::string mode = argv[2];
	const auto sweeps = obs::RawlogReader::read(argv[1]).sweeps;
	const auto config = maps::MapConfig::load(core::ConfigPaths::find("whisker-map.ini"));
	std::vector<double> cpu, wall;
	std::unique_ptr<mrpt::maps::CMultiMetricMap> multimap;
	for (int r = 0; r < std::stoi(argv[3]); r++)
	{
		multimap = std::make_unique<mrpt::maps::CMultiMetricMap>(config);
		auto map = multimap->mapByClass<maps::CHierarchicalObjectMap>();
		using TMode = maps::CHierarchicalObjectMap::TInsertionOptions::TMode;
		map->insertionOptions.mode = mode == "lasting" ? TMode::Lasting : TMode::PerPose;
		map->insertionOptions.keep_history = false;
		const auto t0 = std::chrono::steady_clock::now();
		const std::clock_t c0 = std::clock();
		for (const auto& s : sweeps) multimap->insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		cpu.push_back(cpuUs(c0) / sweeps.size());
		wall.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / sweeps.size());
	}
	std::sort(cpu.begin(), cpu.end());
	std::printf("C++    %-8s %zu sweeps x %zu: cpu best %.1f median %.1f us/sweep; wall best %.1f us/sweep\n", mode.c_str(),
				sweeps.size(), cpu.size(), cpu.front(), cpu[cpu.size() / 2], *std::min_element(wall.begin(), wall.end()));

	const auto& map = *multimap->mapByClass<maps::CHierarchicalObjectMap>();
	double sink = 0;
	const std::clock_t c0 = std::clock();
	for (const auto& s : sweeps)
		for (int j = 0; j < 64; j++)
		{
			const mrpt::poses::CPose2D p(s.robotPose.x() + 0.01 * (j % 8), s.robotPose.y() + 0.01 * (j / 8), s.robotPose.phi());
			sink += map.computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(p));
		}
	std::printf("C++    %-8s likelihood: %.2f us/call (sum %.6g)\n", mode.c_str(), cpuUs(c0) / (64.0 * sweeps.size()), sink);
	return 0;
}
