#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/cli/MapRunner.h>
#include <whiskermap/cli/SlamSmoothing.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/RawlogReader.h>

#include <optional>
#include <string>

namespace whiskermap::cli
{
smooth::PathSmoother::TInput SlamSmoothing::read(size_t sweeps) const
{
	smooth::PathSmoother::TInput in;
	std::optional<mrpt::poses::CPose2D> last;  // the previous sweep's odometry
	obs::RawlogReader::forEach(m_rawlog, [&](const obs::RawlogReader::Sweep& sw) {
		if (in.increments.size() >= sweeps) return;
		const mrpt::poses::CPose2D u = sw.robotPose - (last ? *last : sw.robotPose);
		last = sw.robotPose;
		mrpt::obs::CActionRobotMovement2D move;
		move.computeFromOdometry(u, m_slam.motionModel(u));
		const auto i = static_cast<uint32_t>(in.increments.size());
		in.increments.emplace_back(u.x(), u.y(), u.phi());
		in.covariances.push_back(move.poseChange->getCovariance().asEigen());
		const auto contacts = baseline::Contact::of({mrpt::poses::CPose2D(), sw.obs}, i);  // robot frame
		in.contacts.insert(in.contacts.end(), contacts.begin(), contacts.end());
	});
	if (in.increments.size() < sweeps) throw shorter(m_rawlog, in.increments.size(), sweeps);
	return in;
}

core::Error SlamSmoothing::shorter(const std::string& rawlog, size_t found, size_t read)
{
	return core::Error(rawlog + ": " + std::to_string(found) + " sweeps where the filter read " + std::to_string(read) +
					   " (the file changed during the run?)");
}

std::vector<world::Obstacle> SlamSmoothing::solidsAt(
	const std::vector<Eigen::Vector3d>& path, const mrpt::maps::TSetOfMetricMapInitializers& maps) const
{
	mrpt::maps::CMultiMetricMap multimap(maps);
	auto map = multimap.mapByClass<maps::CHierarchicalObjectMap>();
	if (!map) throw core::Error("whisker-slam: the map config holds no hierarchicalObjectMap");
	MapRunner runner(multimap, *map, 1, [](size_t, const obs::RawlogReader::Sweep&, double) {});
	size_t k = 0;
	obs::RawlogReader::forEach(m_rawlog, [&](const obs::RawlogReader::Sweep& sw) {
		if (k >= path.size()) return;
		const auto& x = path[k++];
		runner.add({mrpt::poses::CPose2D(x[0], x[1], x[2]), sw.obs});
	});
	runner.flush();
	map->annealPending();
	return map->mappedSolids();
}

smooth::PathSmoother::TResult SlamSmoothing::run(
	std::vector<Eigen::Vector3d> path, std::vector<world::Obstacle> solids, const smooth::TSmoothParams& params,
	const mrpt::maps::TSetOfMetricMapInitializers& maps) const
{
	auto in = read(path.size());
	in.path = std::move(path), in.solids = std::move(solids);
	auto result = smooth::PathSmoother::run(in, params);
	for (unsigned pass = 1; pass < params.passes && result.rounds > 0; pass++)  // no rounds: nothing estimated (exact odometry), nothing to redo
	{
		in.solids = solidsAt(result.path, maps);
		in.path = result.path;
		const auto before = result;
		result = smooth::PathSmoother::run(in, params);
		result.costBefore = before.costBefore;  // at the particle's path
		result.rounds += before.rounds, result.iterations += before.iterations;
		result.bridges += before.bridges, result.bridgesTried += before.bridgesTried;
		result.stretches += before.stretches, result.stretchesTried += before.stretchesTried;
	}
	return result;
}
}  // namespace whiskermap::cli
