#pragma once
#include <Eigen/Core>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/TBaselineParams.h>

#include <vector>

namespace whiskermap::baseline
{
/** A square leg of the known width fitted to a cluster of contacts by least squares: each
 *  contact lies on the face whose outward normal matches its own (FaceResidual), its
 *  distance to that face and its normal's angle scored in standard deviations (Huber's loss,
 *  so a stray contact cannot drag the leg), plus a weak prior (one leg width) towards the
 *  mean of the centres the contacts point at, which only matters along a face when a single
 *  face was touched. */
struct LegFit
{
	Eigen::Vector2d centre{0, 0};  ///< metres
	double yaw = 0;  ///< radians in [0, pi/2): a square leg is the same every quarter turn
	Eigen::Matrix2d centreCovariance = Eigen::Matrix2d::Identity();  ///< metres^2
	double yawSigma = 0;  ///< radians
	std::vector<size_t> members;  ///< indices of its contacts
	size_t outliers = 0;  ///< members beyond the outlier gate of their face
	int faces = 0;  ///< distinct faces touched
	double texture = 0;  ///< mean texture of the members

	static LegFit fit(const std::vector<Contact>& contacts, std::vector<size_t> members, const TBaselineParams& p);

	/** Consistent with one square leg: at most outlier_fraction of the members are outliers. */
	bool legShaped(const TBaselineParams& p) const;

	/** The centre a contact points at: half a leg width behind it, against its normal. */
	static Eigen::Vector2d pointedCentre(const Contact& c, double legWidth);
};
}  // namespace whiskermap::baseline
