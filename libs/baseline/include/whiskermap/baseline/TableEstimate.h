#pragma once
#include <Eigen/Core>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/LegFit.h>
#include <whiskermap/baseline/TBaselineParams.h>

#include <array>
#include <vector>

namespace whiskermap::baseline
{
/** A table found by the batch fit: the known table at a pose, with the legs (indices into
 *  the extracted legs) that sit at its corners. Corners are numbered as in the world format:
 *  0 (+x, +y), 1 (-x, +y), 2 (-x, -y), 3 (+x, -y) in the table frame. */
struct TableEstimate
{
	Eigen::Vector2d centre{0, 0};  ///< metres
	double yaw = 0;  ///< radians
	std::array<int, 4> legs{-1, -1, -1, -1};  ///< per corner: leg index, or -1 (not touched)
	double cost = 0;  ///< least-squares cost of the last fit
	size_t contacts = 0;  ///< contacts on its legs
	double texture = 0;  ///< their mean texture

	int legCount() const;
	/** Corner k's leg centre in the table frame. */
	static Eigen::Vector2d offset(int k, const TBaselineParams& p);
	/** Corner k's leg centre in the world. */
	Eigen::Vector2d corner(int k, const TBaselineParams& p) const;
	/** True when the two tables' footprints (legs included) overlap. */
	bool overlaps(const TableEstimate& o, const TBaselineParams& p) const;

	/** Least-squares pose from every contact of its legs: each contact on the face of its
	 *  leg that matches its normal (FaceResidual, Huber's loss), the legs rigidly at the
	 *  corners and turned with the table. Updates centre, yaw, cost, contacts, texture. */
	void fitToContacts(const std::vector<LegFit>& fits, const std::vector<Contact>& all, const TBaselineParams& p);
};
}  // namespace whiskermap::baseline
