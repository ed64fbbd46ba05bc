#pragma once
#include <cmath>
#include <vector>

namespace whiskermap::eval
{
/** The scores of one estimated set of tables against a true one (doc/evaluation.md).
 *  rmse_m and yaw_err_deg are NaN when nothing was matched, rmse_aligned_m below three
 *  matched (written as null in JSON). */
struct Figures
{
	double precision = 1;  ///< matched / estimated (1 when nothing was estimated)
	double recall = 1;  ///< matched / true (1 when there is nothing to find)
	double f1 = 1;  ///< 2 P R / (P + R), 0 when P + R = 0
	double count_error = 0;  ///< estimated - true
	double rmse_m = NAN;  ///< root mean square centre error over matched pairs, metres
	double yaw_err_deg = NAN;  ///< mean absolute yaw error modulo 180 deg over matched pairs
	double ospa = 0;  ///< OSPA of the table centres, metres
	/** Centre RMSE over the matched pairs after the best planar rigid motion of the matched
	 *  estimated centres onto the true ones (Se2Alignment), metres: the map's shape without
	 *  its registration (a SLAM map carries its path's offset whole). */
	double rmse_aligned_m = NAN;

	/** Figures of a matching: `matched` pairs with these summed squared centre errors and
	 *  summed absolute yaw errors; `ospaValue` computed by the caller. */
	static Figures of(
		size_t estimated, size_t truth, size_t matched, double sumSqCentre, double sumYawDeg,
		double ospaValue);

	/** Mean of each figure over `items`; rmse_m, yaw_err_deg and rmse_aligned_m over the
	 *  items where they are defined (NaN if none). All fields keep their defaults when `items` is empty. */
	static Figures mean(const std::vector<Figures>& items);

};
}  // namespace whiskermap::eval
