#include <whiskermap/core/Error.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/PerPoseEvaluation.h>

#include <cmath>
#include <string>

namespace whiskermap::eval
{
PerPoseEvaluation::Accumulator::Accumulator(
	std::vector<world::Table> truth, const EvalOptions& opts, bool withLocal)
	: m_truth(std::move(truth)), m_opts(opts), m_withLocal(withLocal)
{
}

void PerPoseEvaluation::Accumulator::add(
	const std::vector<world::Table>& tables, const mrpt::poses::CPose2D& robotPose)
{
	m_poses++;
	m_all.add(MapEvaluation::compute(m_truth, tables, m_opts).figures);
	if (!m_withLocal) return;
	m_near.clear();
	for (const auto& t : m_truth)
		if (std::hypot(t.x - robotPose.x(), t.y - robotPose.y()) <= m_opts.local_radius) m_near.push_back(t);
	m_local.add(MapEvaluation::compute(m_near, tables, m_opts).figures);
}

PerPoseEvaluation PerPoseEvaluation::Accumulator::result() const
{
	PerPoseEvaluation e;
	e.poses = m_poses;
	e.all = m_all.result();
	if (m_withLocal) e.local = m_local.result();
	return e;
}

PerPoseEvaluation PerPoseEvaluation::compute(
	const std::vector<world::Table>& truth, const std::vector<std::vector<world::Table>>& perPose,
	const std::vector<mrpt::poses::CPose2D>& robotPoses, const EvalOptions& opts)
{
	const bool withLocal = !robotPoses.empty();
	if (withLocal && robotPoses.size() != perPose.size())
		throw core::Error(
			"per-pose evaluation: " + std::to_string(perPose.size()) + " poses but " +
			std::to_string(robotPoses.size()) + " robot poses");
	Accumulator acc(truth, opts, withLocal);
	for (size_t i = 0; i < perPose.size(); i++)
		acc.add(perPose[i], withLocal ? robotPoses[i] : mrpt::poses::CPose2D());
	return acc.result();
}
}  // namespace whiskermap::eval
