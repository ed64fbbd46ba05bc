#pragma once
#include <Eigen/Core>
#include <whiskermap/obs/RawlogReader.h>

#include <cstdint>
#include <vector>

namespace whiskermap::baseline
{
/** One whisker contact in the world frame, as the batch fit uses it: the shapelet
 *  (CObservationWhiskerContacts::toShapelets) plus the whisker's shaft direction and the
 *  reading noise its sweep reports. The shaft angle comes from the actuator (exact); the
 *  radial distance r is the noisy reading, so a contact is uncertain along its shaft only. */
struct Contact
{
	Eigen::Vector2d p{0, 0};  ///< contact point, metres
	double normal = 0;  ///< outward surface-normal angle, radians
	double texture = 0;
	Eigen::Vector2d shaft{1, 0};  ///< unit direction of the shaft, pivot to contact
	double sigma_r = 0, sigma_phi = 0, sigma_tau = 0;  ///< the sweep's reading noise
	uint32_t sweep = 0;  ///< index of its sweep in the rawlog

	/** The contacts of one sweep, in whisker order. */
	static std::vector<Contact> of(const obs::RawlogReader::Sweep& sweep, uint32_t index);
};
}  // namespace whiskermap::baseline
