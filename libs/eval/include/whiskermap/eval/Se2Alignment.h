#pragma once
#include <Eigen/Core>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace whiskermap::eval
{
/** A planar rigid motion (rotation `yaw` about the origin, then translation `t`) that best
 *  maps one set of points onto another, paired by index: the least-squares fit without scale
 *  (Horn's / Umeyama's closed form, which in 2-D is one atan2). */
struct Se2Alignment
{
	double yaw = 0;  ///< radians
	Eigen::Vector2d t = Eigen::Vector2d::Zero();  ///< metres

	/** Minimises sum_i |R(yaw) from_i + t - to_i|^2. Equal, non-empty sizes (throws
	 *  core::Error otherwise); with one point, or all points equal, the yaw is 0. */
	static Se2Alignment fit(const std::vector<Eigen::Vector2d>& from, const std::vector<Eigen::Vector2d>& to);
	/** The same fit from the sets' means and their centred sums sum f'.g' (`dot`) and
	 *  sum f' x g' (`cross`): what fit() computes, for points streamed in two passes. */
	static Se2Alignment fromMoments(
		const Eigen::Vector2d& meanFrom, const Eigen::Vector2d& meanTo, double dot, double cross);

	Eigen::Vector2d apply(const Eigen::Vector2d& p) const;
	/** A pose moved as a whole: position mapped, heading turned by yaw. */
	mrpt::poses::CPose2D apply(const mrpt::poses::CPose2D& p) const;
};
}  // namespace whiskermap::eval
