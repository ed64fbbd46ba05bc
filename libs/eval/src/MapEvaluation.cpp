#include <whiskermap/core/Angles.h>
#include <whiskermap/eval/SparseAssignment.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/Ospa.h>

namespace whiskermap::eval
{
namespace
{
std::vector<Eigen::Vector2d> centres(const std::vector<world::Table>& tables)
{
	std::vector<Eigen::Vector2d> c;
	for (const auto& t : tables) c.emplace_back(t.x, t.y);
	return c;
}
}  // namespace

MapEvaluation MapEvaluation::compute(
	const std::vector<world::Table>& truth, const std::vector<world::Table>& estimated,
	const EvalOptions& opts)
{
	opts.validate();
	const auto est = centres(estimated), tru = centres(truth);
	// Rows: true tables, columns: estimated ones; only pairs within the centre gate are
	// scored (a grid finds them), and the assignment is solved per connected component.
	// Yaw error modulo 180 degrees (symmetry).
	std::vector<SparseAssignment::Pair> pairs;
	std::vector<double> yawErr;
	for (const auto& p : SparseAssignment::near(tru, est, opts.gate_distance))
	{
		const double yaw = core::rad2deg(std::abs(core::angleDiff(estimated[p.col].yaw, truth[p.row].yaw, M_PI)));
		if (yaw > opts.gate_yaw_deg) continue;
		pairs.push_back(p);
		yawErr.push_back(yaw);
	}

	MapEvaluation e;
	e.estimated = estimated.size();
	e.truth = truth.size();
	e.truthMatch = SparseAssignment::solve(static_cast<int>(truth.size()), static_cast<int>(estimated.size()), pairs, INFINITY);
	double sumSq = 0, sumYaw = 0;
	for (size_t k = 0; k < pairs.size(); k++)
	{
		if (e.truthMatch[pairs[k].row] != pairs[k].col) continue;
		e.matched++;
		sumSq += pairs[k].cost * pairs[k].cost;
		sumYaw += yawErr[k];
	}
	e.figures = Figures::of(
		e.estimated, e.truth, e.matched, sumSq, sumYaw,
		Ospa::distance(est, tru, opts.ospa_c, opts.ospa_p));
	return e;
}
}  // namespace whiskermap::eval
