#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TrajectoryEvaluation.h>

#include <algorithm>
#include <cstdio>

namespace whiskermap::eval
{
namespace
{
constexpr double TIME_TOLERANCE = 1e-6;  // seconds: path files hold microseconds

Eigen::Vector2d xy(const mrpt::math::TPose2D& p) { return {p.x, p.y}; }
mrpt::poses::CPose2D pose(const world::PathLog::Entry& e) { return mrpt::poses::CPose2D(e.pose); }

std::string at(const std::string& label, const world::PathLog::Entry& e)
{
	return e.line > 0 ? label + ": line " + std::to_string(e.line) : label;
}
}  // namespace

TrajectoryEvaluation TrajectoryEvaluation::compute(
	const std::vector<world::PathLog::Entry>& est, const std::vector<world::PathLog::Entry>& truth,
	const EvalOptions& opts, const std::string& estLabel, const std::string& truthLabel)
{
	opts.validate();
	if (est.empty() || truth.empty()) throw core::Error((est.empty() ? estLabel : truthLabel) + ": no poses");
	if (est.size() != truth.size())
		throw core::Error(
			estLabel + ": holds " + std::to_string(est.size()) + " poses, but " + truthLabel + " holds " +
			std::to_string(truth.size()) + " (one line per sweep in both)");
	for (size_t i = 0; i < est.size(); i++)
		if (std::abs(est[i].t - truth[i].t) > TIME_TOLERANCE)
		{
			char buf[160];
			std::snprintf(buf, sizeof(buf), ": timestamp %.6f, but %.6f at ", est[i].t, truth[i].t);
			throw core::Error(at(estLabel, est[i]) + buf + at(truthLabel, truth[i]));
		}

	TrajectoryEvaluation r;
	const size_t n = est.size();
	r.poses = n;
	std::vector<Eigen::Vector2d> pe(n), pt(n);
	std::vector<double> s(n, 0);  // true distance travelled up to each pose
	double sumSq = 0, sumYawSq = 0;
	for (size_t i = 0; i < n; i++)
	{
		pe[i] = xy(est[i].pose), pt[i] = xy(truth[i].pose);
		if (i > 0) s[i] = s[i - 1] + (pt[i] - pt[i - 1]).norm();
		const double e = (pe[i] - pt[i]).norm();
		sumSq += e * e;
		r.ate_max_m = std::max(r.ate_max_m, e);
		const double yaw = core::wrapToPi(est[i].pose.phi - truth[i].pose.phi);
		sumYawSq += yaw * yaw;
	}
	r.length_m = s.back();
	r.ate_rmse_m = std::sqrt(sumSq / n);
	r.ate_yaw_rmse_deg = core::rad2deg(std::sqrt(sumYawSq / n));
	r.final_error_m = (pe.back() - pt.back()).norm();
	r.final_yaw_err_deg = core::rad2deg(std::abs(core::wrapToPi(est.back().pose.phi - truth.back().pose.phi)));

	r.alignment = Se2Alignment::fit(pe, pt);
	double alignedSq = 0;
	for (size_t i = 0; i < n; i++)
	{
		const double e = (r.alignment.apply(pe[i]) - pt[i]).norm();
		alignedSq += e * e;
		r.aligned_max_m = std::max(r.aligned_max_m, e);
	}
	r.aligned_rmse_m = std::sqrt(alignedSq / n);

	// RPE: from each pose i to the first pose j with s_j - s_i >= segment, the error of the
	// estimated relative motion, E = (T_i^-1 T_j)^-1 (P_i^-1 P_j), per metre of true travel.
	double sumTrans = 0, sumRot = 0;
	for (size_t i = 0, j = 0; i < n; i++)
	{
		j = std::max(j, i + 1);
		while (j < n && s[j] - s[i] < opts.rpe_segment_m) j++;
		if (j >= n) break;
		const double d = s[j] - s[i];
		const auto E = (pose(truth[j]) - pose(truth[i])) - (pose(est[j]) - pose(est[i]));
		sumTrans += std::hypot(E.x(), E.y()) / d;
		sumRot += std::abs(core::wrapToPi(E.phi())) / d;
		r.rpe_segments++;
	}
	if (r.rpe_segments)
	{
		r.rpe_trans = sumTrans / r.rpe_segments;
		r.rpe_rot_deg_per_m = core::rad2deg(sumRot / r.rpe_segments);
	}
	return r;
}
}  // namespace whiskermap::eval
