#pragma once
#include <Eigen/Core>

namespace whiskermap::smooth
{
/** Two mapped solids that are one (doc/slam.md, "Tables mapped twice"): once shifted by their
 *  groups' shifts, they stand in one place along the directions P holds,
 *    r = P (c_a + d_a - c_b - d_b) / sigma,
 *  - a leg mapped twice (DuplicateLegs): P = I, the two centres coincide (eq. S4);
 *  - a wall mapped twice (DuplicateWalls): P = n n^T, the two lines coincide across (eq. S5),
 *    and each piece still slides along itself.
 *  It closes the loop a particle's map left open: the contacts tied to each copy pull the
 *  path of their own visit onto the one solid. */
struct SameSolidFactor
{
	size_t a = 0, b = 0;  ///< the two solids' groups
	Eigen::Vector2d offset{0, 0};  ///< c_a - c_b, points of the two as mapped (centres; any point of each line for walls)
	double sigma = 1;
	Eigen::Matrix2d P = Eigen::Matrix2d::Identity();  ///< the directions held: I, or n n^T across a wall

	/** The whitened residual at shifts da, db; its Jacobians are P / sigma and -P / sigma. */
	Eigen::Vector2d residual(const Eigen::Vector2d& da, const Eigen::Vector2d& db) const
	{
		return P * (offset + da - db) / sigma;  // eqs. S4, S5
	}

	/** Coordinates it holds: 2 for a leg, 1 for a wall (the trace of P). */
	double dof() const { return P.trace(); }
};
}  // namespace whiskermap::smooth
