#pragma once
#include <Eigen/Core>
#include <whiskermap/smooth/OdometryFactor.h>

#include <utility>
#include <vector>

namespace whiskermap::smooth
{
/** Stretches where a smoothed path strays from its odometry, and the odometry's own path
 *  across them (eq. S8, doc/slam.md, "Bridging where the path strays").
 *
 *  A filter that locks onto the wrong legs for a while (a table's legs look alike) leaves a
 *  path whose contacts tie to those legs; the smoother, which only refines, keeps the bend.
 *  Such a bend shows as a window of `window` sweeps over which the path's motion differs from
 *  the odometry's by more than the odometry's covariance allows:
 *    m^2 = e^T C_w^-1 e,  e = (x_a^-1 (+) x_b) - (u_a+1 (+) ... (+) u_b),  b = a + window,
 *  C_w the increments' covariances composed along the window (eq. S8). */
struct OdometryBridge
{
	using Path = std::vector<Eigen::Vector3d>;
	using Stretch = std::pair<size_t, size_t>;  ///< first and last sweep

	/** m of every window of `path` (odometry[i] leads from sweep i-1 to i): entry a for
	 *  sweeps a..a + window (none when the path is shorter than a window). */
	static std::vector<double> distances(const Path& path, const std::vector<OdometryFactor>& odometry, size_t window);

	/** The stretches covered by windows whose m (`distances`) exceeds `gate`; windows closer
	 *  than `window` sweeps join one stretch. */
	static std::vector<Stretch> strays(const std::vector<double>& m, size_t window, double gate);

	/** The largest of `m` (0 when there is none). */
	static double worst(const std::vector<double>& m);

	/** The candidate stretches to bridge: each stray stretch, and each two neighbours together
	 *  (a bend leaves the odometry where it begins and where it ends, and between them the path
	 *  may follow the odometry, shifted), each widened by `margin` sweeps on both sides within
	 *  the path's `n` (a bend may begin where the odometry is loose, in a turn, and show only
	 *  after it). */
	static std::vector<Stretch> candidates(const std::vector<Stretch>& strays, size_t margin, size_t n);

	/** `path` with sweeps a..b replaced by the odometry's chain from path[a], the gap it leaves
	 *  at b spread linearly over the stretch so that it ends at path[b]. */
	static Path bridge(const Path& path, const std::vector<OdometryFactor>& odometry, Stretch s);
};
}  // namespace whiskermap::smooth
