#pragma once
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/Se2Alignment.h>
#include <whiskermap/world/PathLog.h>

#include <cmath>
#include <string>
#include <vector>

namespace whiskermap::eval
{
/** An estimated robot path scored against the true one, pose by pose (definitions:
 *  doc/evaluation.md, "Trajectory figures"). */
struct TrajectoryEvaluation
{
	size_t poses = 0;
	double length_m = 0;  ///< true path length
	double ate_rmse_m = 0, ate_max_m = 0;  ///< position error as estimated (raw)
	double ate_yaw_rmse_deg = 0;  ///< heading error as estimated
	Se2Alignment alignment;  ///< the best SE(2) map of the estimate onto the truth
	double aligned_rmse_m = 0, aligned_max_m = 0;  ///< position error after it
	size_t rpe_segments = 0;  ///< segments of at least rpe_segment_m of true travel
	double rpe_trans = NAN;  ///< mean translation drift, metres per metre (NaN: no segment)
	double rpe_rot_deg_per_m = NAN;  ///< mean heading drift, degrees per metre
	double final_error_m = 0, final_yaw_err_deg = 0;  ///< at the last pose, raw

	/** `estimated` and `truth` must pair one to one: same count, same timestamps (within
	 *  1 microsecond); otherwise core::Error naming `estLabel`'s line and `truthLabel`'s. */
	static TrajectoryEvaluation compute(
		const std::vector<world::PathLog::Entry>& estimated, const std::vector<world::PathLog::Entry>& truth,
		const EvalOptions& opts, const std::string& estLabel = "estimated path",
		const std::string& truthLabel = "true path");

	/** The same figures for two path files (world::PathLog), streamed: each file is read
	 *  four times (once to check and count, three passes of the figures), so memory does
	 *  not grow with the paths (only RPE's window: the poses of the last rpe_segment_m of
	 *  true travel, at most RPE_WINDOW). `limit` > 0 scores the first `limit` poses of each
	 *  file (both must hold that many); 0 scores them whole (equal counts). */
	static TrajectoryEvaluation compute(
		const std::string& estimatedFile, const std::string& truthFile, const EvalOptions& opts, size_t limit = 0);

	/** RPE's window bound: a segment whose start lies more poses back is not scored (a
	 *  robot standing still for millions of sweeps). */
	static constexpr size_t RPE_WINDOW = size_t(1) << 22;
};
}  // namespace whiskermap::eval
