#pragma once
#include <Eigen/Core>
#include <whiskermap/baseline/Contact.h>
#include <whiskermap/baseline/LeastSquares.h>
#include <whiskermap/baseline/TBaselineParams.h>

namespace whiskermap::baseline
{
/** How far a contact is from a face of a square leg (centre, yaw, side leg_width), in
 *  standard deviations. The contact is noisy along its shaft only, so its distance to a face
 *  with outward normal n has std-dev sigma_r |n . shaft| (+ the position floor); its normal
 *  differs from n by sigma_phi (+ the angle floor). Face k has outward normal yaw + k pi/2. */
struct FaceResidual
{
	int face = 0;
	double point = 0;  ///< (n . (p - centre) - w/2) / sigma: signed distance to the face's line
	double normal = 0;  ///< angle from the face normal to the contact's, / sigma
	double beyond = 0;  ///< how far past the face's ends along it, / sigma (0 when within)

	/** On face `face`. */
	static FaceResidual on(
		const Contact& c, const Eigen::Vector2d& centre, double yaw, int face, const TBaselineParams& p);
	/** On the face that fits it best (least point^2 + normal^2 + beyond^2). */
	static FaceResidual best(const Contact& c, const Eigen::Vector2d& centre, double yaw, const TBaselineParams& p);

	/** point^2 + normal^2 + beyond^2. */
	double cost() const { return point * point + normal * normal + beyond * beyond; }
	/** True when any of the three exceeds the outlier gate. */
	bool outlier(const TBaselineParams& p) const;

	/** A contact of a rigid set of square legs posed at (x, y, yaw): its leg's centre sits at
	 *  `offset` in that frame, and the leg turns with the frame. */
	struct Member
	{
		size_t contact;
		Eigen::Vector2d offset;
	};

	/** Least-squares pose of such a set from its contacts: the three residuals of each
	 *  contact on its face (Huber's loss), plus `prior`'s residuals if given; faces are
	 *  reassigned to the best fitting ones and the fit repeated, up to 4 rounds. */
	static LeastSquares::Result fitPose(
		const std::vector<Contact>& contacts, const std::vector<Member>& members, const Eigen::Vector3d& start,
		const TBaselineParams& p, const LeastSquares::Residuals& prior = nullptr);
};
}  // namespace whiskermap::baseline
