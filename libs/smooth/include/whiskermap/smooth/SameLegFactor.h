#pragma once
#include <Eigen/Core>

namespace whiskermap::smooth
{
/** Two mapped legs that are one leg (DuplicateLegs): once shifted by their groups' shifts,
 *  their centres coincide (eq. S4, doc/slam.md),
 *    r = (c_a + d_a - c_b - d_b) / sigma.
 *  It closes the loop a particle's map left open: the contacts tied to each copy pull the
 *  path of their own visit onto the one leg. */
struct SameLegFactor
{
	size_t a = 0, b = 0;  ///< the two legs' groups
	Eigen::Vector2d offset{0, 0};  ///< c_a - c_b, the centres as mapped
	double sigma = 1;

	/** The whitened residual at shifts da, db; its Jacobians are I / sigma and -I / sigma. */
	Eigen::Vector2d residual(const Eigen::Vector2d& da, const Eigen::Vector2d& db) const
	{
		return (offset + da - db) / sigma;  // eq. S4
	}
};
}  // namespace whiskermap::smooth
