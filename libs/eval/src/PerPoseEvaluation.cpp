#include <whiskermap/core/Error.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/PerPoseEvaluation.h>

#include <cmath>
#include <string>

namespace whiskermap::eval
{
PerPoseEvaluation PerPoseEvaluation::compute(
	const std::vector<world::Table>& truth, const std::vector<std::vector<world::Table>>& perPose,
	const std::vector<mrpt::poses::CPose2D>& robotPoses, const EvalOptions& opts)
{
	const bool withLocal = !robotPoses.empty();
	if (withLocal && robotPoses.size() != perPose.size())
		throw core::Error(
			"per-pose evaluation: " + std::to_string(perPose.size()) + " poses but " +
			std::to_string(robotPoses.size()) + " robot poses");
	std::vector<Figures> all, local;
	for (size_t i = 0; i < perPose.size(); i++)
	{
		all.push_back(MapEvaluation::compute(truth, perPose[i], opts).figures);
		if (!withLocal) continue;
		std::vector<world::Table> near;
		for (const auto& t : truth)
			if (std::hypot(t.x - robotPoses[i].x(), t.y - robotPoses[i].y()) <= opts.local_radius)
				near.push_back(t);
		local.push_back(MapEvaluation::compute(near, perPose[i], opts).figures);
	}
	PerPoseEvaluation e;
	e.poses = perPose.size();
	e.all = Figures::mean(all);
	if (withLocal) e.local = Figures::mean(local);
	return e;
}
}  // namespace whiskermap::eval
