// insert_loop RAWLOG MODE REPEATS: the C++ half of scripts/bench-python.sh. Times inserting
// every sweep of the rawlog into a fresh map (shipped config, keep_history off as in
// whisker-map), REPEATS times, and prints the best and median microseconds per sweep in the
// same line format as insert_loop.py.
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace whiskermap;

int main(int argc, char** argv)
{
	if (argc != 4)
	{
		std::fprintf(stderr, "usage: insert_loop RAWLOG lasting|per_pose REPEATS\n");
		return 1;
	}
	const std::string mode = argv[2];
	const auto sweeps = obs::RawlogReader::read(argv[1]).sweeps;
	const auto config = maps::MapConfig::load(core::ConfigPaths::find("whisker-map.ini"));
	std::vector<double> us;
	for (int r = 0; r < std::stoi(argv[3]); r++)
	{
		mrpt::maps::CMultiMetricMap multimap(config);
		auto map = multimap.mapByClass<maps::CHierarchicalObjectMap>();
		using TMode = maps::CHierarchicalObjectMap::TInsertionOptions::TMode;
		map->insertionOptions.mode = mode == "lasting" ? TMode::Lasting : TMode::PerPose;
		map->insertionOptions.keep_history = false;
		const auto t0 = std::chrono::steady_clock::now();
		for (const auto& s : sweeps) multimap.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / sweeps.size());
	}
	std::sort(us.begin(), us.end());
	std::printf("C++    %-8s %zu sweeps x %zu: best %.1f us/sweep, median %.1f us/sweep\n", mode.c_str(), sweeps.size(),
				us.size(), us.front(), us[us.size() / 2]);
	return 0;
}
