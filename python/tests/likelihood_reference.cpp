// likelihood_reference RAWLOG MODE SEED: the C++ side of test_map.py's likelihood test. Builds
// the map from every sweep of the rawlog (shipped config, given mode and seed, as whisker-map
// does), then prints for each sweep its log-likelihood at its own pose and at the pose moved by
// (0.05 m, -0.03 m, 0.1 rad), as "%.17g %.17g" (exact doubles).
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/conciseMessage.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/obs/RawlogReader.h>

#include <cstdio>
#include <iostream>
#include <string>

using namespace whiskermap;

int main(int argc, char** argv)
try
{
	if (argc != 4)
	{
		std::cerr << "usage: likelihood_reference RAWLOG lasting|per_pose SEED\n";
		return 1;
	}
	mrpt::maps::CMultiMetricMap multimap(maps::MapConfig::load(core::ConfigPaths::find("whisker-map.ini")));
	auto map = multimap.mapByClass<maps::CHierarchicalObjectMap>();
	using TMode = maps::CHierarchicalObjectMap::TInsertionOptions::TMode;
	map->insertionOptions.mode = std::string(argv[2]) == "lasting" ? TMode::Lasting : TMode::PerPose;
	map->insertionOptions.seed = std::stoull(argv[3]);
	const auto sweeps = obs::RawlogReader::read(argv[1]).sweeps;
	for (const auto& s : sweeps) multimap.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
	for (const auto& s : sweeps)
	{
		const mrpt::poses::CPose2D moved(s.robotPose.x() + 0.05, s.robotPose.y() - 0.03, s.robotPose.phi() + 0.1);
		std::printf(
			"%.17g %.17g\n", map->computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(s.robotPose)),
			map->computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(moved)));
	}
	return 0;
}
catch (const std::exception& e)
{
	std::cerr << "likelihood_reference: error: " << core::conciseMessage(e) << "\n";
	return 1;
}
