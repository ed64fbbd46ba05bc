#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TrajectoryEvaluation.h>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <functional>

namespace whiskermap::eval
{
namespace
{
using Entry = world::PathLog::Entry;
/** Calls its argument with every (estimated, true) pair, in order; called once per pass. */
using Pairs = std::function<void(const std::function<void(const Entry&, const Entry&)>&)>;

constexpr double TIME_TOLERANCE = 1e-6;  // seconds: path files hold microseconds

Eigen::Vector2d xy(const mrpt::math::TPose2D& p) { return {p.x, p.y}; }
mrpt::poses::CPose2D pose(const mrpt::math::TPose2D& p) { return mrpt::poses::CPose2D(p); }

std::string at(const std::string& label, const Entry& e)
{
	return e.line > 0 ? label + ": line " + std::to_string(e.line) : label;
}

void checkCounts(size_t nEst, size_t nTruth, const std::string& estLabel, const std::string& truthLabel)
{
	if (nEst != nTruth)
		throw core::Error(
			estLabel + ": holds " + std::to_string(nEst) + " poses, but " + truthLabel + " holds " +
			std::to_string(nTruth) + " (one line per sweep in both)");
}

void checkTimes(const Entry& est, const Entry& truth, const std::string& estLabel, const std::string& truthLabel)
{
	if (std::abs(est.t - truth.t) <= TIME_TOLERANCE) return;
	char buf[160];
	std::snprintf(buf, sizeof(buf), ": timestamp %.6f, but %.6f at ", est.t, truth.t);
	throw core::Error(at(estLabel, est) + buf + at(truthLabel, truth));
}

/** RPE's segments, fed pose by pose: from each pose i to the first pose j with
 *  s_j - s_i >= segment, the error of the estimated relative motion,
 *  E = (T_i^-1 T_j)^-1 (P_i^-1 P_j), per metre of true travel. */
class RpeWindow
{
   public:
	explicit RpeWindow(double segment) : m_segment(segment) {}

	void add(double s, const Entry& est, const Entry& truth)
	{
		// Every open start this pose is the first to close, oldest first (the order of i).
		while (!m_open.empty() && s - m_open.front().s >= m_segment)
		{
			const auto& i = m_open.front();
			const double d = s - i.s;
			const auto E = (pose(truth.pose) - pose(i.truth)) - (pose(est.pose) - pose(i.est));
			m_trans += std::hypot(E.x(), E.y()) / d;
			m_rot += std::abs(core::wrapToPi(E.phi())) / d;
			m_segments++;
			m_open.pop_front();
		}
		if (m_open.size() == TrajectoryEvaluation::RPE_WINDOW) m_open.pop_front();
		m_open.push_back({s, est.pose, truth.pose});
	}

	void finish(TrajectoryEvaluation& r) const
	{
		r.rpe_segments = m_segments;
		if (!m_segments) return;
		r.rpe_trans = m_trans / m_segments;
		r.rpe_rot_deg_per_m = core::rad2deg(m_rot / m_segments);
	}

   private:
	struct Start
	{
		double s;
		mrpt::math::TPose2D est, truth;
	};
	double m_segment, m_trans = 0, m_rot = 0;
	size_t m_segments = 0;
	std::deque<Start> m_open;
};

/** The figures in three passes over the pairs (doc/evaluation.md, "Trajectory figures"). */
TrajectoryEvaluation evaluate(const Pairs& pairs, const EvalOptions& opts)
{
	TrajectoryEvaluation r;
	// Pass 1: raw errors, true length, final error, RPE, the means for the alignment.
	double sumSq = 0, sumYawSq = 0, s = 0;
	Eigen::Vector2d sumEst = Eigen::Vector2d::Zero(), sumTruth = Eigen::Vector2d::Zero(), lastTruth;
	RpeWindow rpe(opts.rpe_segment_m);
	pairs([&](const Entry& est, const Entry& truth) {
		const Eigen::Vector2d pe = xy(est.pose), pt = xy(truth.pose);
		if (r.poses > 0) s += (pt - lastTruth).norm();
		lastTruth = pt;
		r.poses++;
		const double e = (pe - pt).norm();
		sumSq += e * e;
		r.ate_max_m = std::max(r.ate_max_m, e);
		const double yaw = core::wrapToPi(est.pose.phi - truth.pose.phi);
		sumYawSq += yaw * yaw;
		sumEst += pe, sumTruth += pt;
		r.final_error_m = e;
		r.final_yaw_err_deg = core::rad2deg(std::abs(yaw));
		rpe.add(s, est, truth);
	});
	const double n = double(r.poses);
	r.length_m = s;
	r.ate_rmse_m = std::sqrt(sumSq / n);
	r.ate_yaw_rmse_deg = core::rad2deg(std::sqrt(sumYawSq / n));
	rpe.finish(r);

	// Pass 2: the centred sums of the best SE(2) alignment (Se2Alignment::fit).
	const Eigen::Vector2d mf = sumEst / n, mt = sumTruth / n;
	double dot = 0, cross = 0;
	pairs([&](const Entry& est, const Entry& truth) {
		const Eigen::Vector2d f = xy(est.pose) - mf, g = xy(truth.pose) - mt;
		dot += f.dot(g);
		cross += f.x() * g.y() - f.y() * g.x();
	});
	r.alignment = Se2Alignment::fromMoments(mf, mt, dot, cross);

	// Pass 3: the errors after it.
	double alignedSq = 0;
	pairs([&](const Entry& est, const Entry& truth) {
		const double e = (r.alignment.apply(xy(est.pose)) - xy(truth.pose)).norm();
		alignedSq += e * e;
		r.aligned_max_m = std::max(r.aligned_max_m, e);
	});
	r.aligned_rmse_m = std::sqrt(alignedSq / n);
	return r;
}
}  // namespace

TrajectoryEvaluation TrajectoryEvaluation::compute(
	const std::vector<Entry>& est, const std::vector<Entry>& truth, const EvalOptions& opts,
	const std::string& estLabel, const std::string& truthLabel)
{
	opts.validate();
	if (est.empty() || truth.empty()) throw core::Error((est.empty() ? estLabel : truthLabel) + ": no poses");
	checkCounts(est.size(), truth.size(), estLabel, truthLabel);
	for (size_t i = 0; i < est.size(); i++) checkTimes(est[i], truth[i], estLabel, truthLabel);
	return evaluate(
		[&](const auto& visit) {
			for (size_t i = 0; i < est.size(); i++) visit(est[i], truth[i]);
		},
		opts);
}

TrajectoryEvaluation TrajectoryEvaluation::compute(
	const std::string& estFile, const std::string& truthFile, const EvalOptions& opts, size_t limit)
{
	opts.validate();
	const size_t all = limit ? limit : SIZE_MAX;
	// Every line of both files checked, and the counts compared, before any figure.
	const size_t nEst = world::PathLog::count(estFile, all), nTruth = world::PathLog::count(truthFile, all);
	if (limit && std::min(nEst, nTruth) < limit)
		throw core::Error(
			(nEst < limit ? estFile : truthFile) + ": holds " + std::to_string(std::min(nEst, nTruth)) +
			" poses, " + std::to_string(limit) + " needed (one line per sweep)");
	checkCounts(nEst, nTruth, estFile, truthFile);
	return evaluate(
		[&](const auto& visit) {
			world::PathLog::Reader re(estFile), rt(truthFile);
			Entry e, t;
			while (re.count() < all && re.next(e) && rt.next(t))
			{
				checkTimes(e, t, estFile, truthFile);
				visit(e, t);
			}
		},
		opts);
}
}  // namespace whiskermap::eval
