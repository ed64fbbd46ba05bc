#pragma once
#include <Eigen/Core>

#include <cmath>

namespace whiskermap::smooth
{
/** Two legs of one mapped table keep the distance the table's shape puts between them (doc/
 *  slam.md, "Tables keep their shape"): once shifted by their groups' shifts,
 *    r = (|c_a + d_a - c_b - d_b| - |c_a - c_b|) / sigma                          (eq. S7)
 *  where c_a - c_b is the legs' offset as mapped (the map's table is rigid, of its class's
 *  size). The distance, not the offset, is held, so the table may turn: a shift per leg lets the
 *  contacts of each visit move its leg, and the legs touched on different visits still tie
 *  those visits together through the table's known size. */
struct TableShapeFactor
{
	size_t a = 0, b = 0;  ///< the two legs' groups
	Eigen::Vector2d offset{0, 0};  ///< c_a - c_b, the legs' centres as mapped (not zero)
	double sigma = 1;

	/** The whitened residual at shifts da, db; with `J`, its Jacobian in da (in db: -J). */
	double residual(const Eigen::Vector2d& da, const Eigen::Vector2d& db, Eigen::RowVector2d* J = nullptr) const
	{
		const Eigen::Vector2d v = offset + da - db;
		const double length = v.norm();
		if (J) *J = v.transpose() / (length * sigma);
		return (length - offset.norm()) / sigma;  // eq. S7
	}
};
}  // namespace whiskermap::smooth
