#include <whiskermap/core/Angles.h>
#include <whiskermap/eval/Hungarian.h>
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
	// Rows: true tables, columns: estimated ones. Yaw error modulo 180 degrees (symmetry).
	Eigen::MatrixXd cost(truth.size(), estimated.size()), yawErr(truth.size(), estimated.size());
	for (size_t i = 0; i < truth.size(); i++)
		for (size_t j = 0; j < estimated.size(); j++)
		{
			const double d = (tru[i] - est[j]).norm();
			yawErr(i, j) =
				core::rad2deg(std::abs(core::angleDiff(estimated[j].yaw, truth[i].yaw, M_PI)));
			const bool allowed = d <= opts.gate_distance && yawErr(i, j) <= opts.gate_yaw_deg;
			cost(i, j) = allowed ? d : INFINITY;
		}

	MapEvaluation e;
	e.estimated = estimated.size();
	e.truth = truth.size();
	e.truthMatch = Hungarian::solve(cost);
	double sumSq = 0, sumYaw = 0;
	for (size_t i = 0; i < truth.size(); i++)
	{
		const int j = e.truthMatch[i];
		if (j < 0) continue;
		e.matched++;
		sumSq += cost(i, j) * cost(i, j);
		sumYaw += yawErr(i, j);
	}
	e.figures = Figures::of(
		e.estimated, e.truth, e.matched, sumSq, sumYaw,
		Ospa::distance(est, tru, opts.ospa_c, opts.ospa_p));
	return e;
}
}  // namespace whiskermap::eval
