#pragma once
#include <mrpt/obs/CObservationRange.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <vector>

namespace whiskermap::obs
{
/** A whisker sweep as stock MRPT range observations: each whisker is one range ray from its
 *  base (pivot) along its shaft at the angle it stopped at, so that MRPT's own
 *  COccupancyGridMap2D (and stock pf-localization / rbpf-slam with a grid) can use the same
 *  contacts (doc/formats.md, "Whisker sweeps as range rays").
 *
 *  One CObservationRange per whisker, holding one measurement: MRPT 2.5.8's grid inserts a
 *  CObservationRange from the pose of its first measurement only, so several whiskers in one
 *  observation would all be drawn along the first one's ray; its likelihood field
 *  (lmLikelihoodField_Thrun) scores every measurement at its own pose either way.
 *  - range: the contact's distance r along the shaft if the whisker touched, else its length;
 *  - sensorPose: the sweep's sensorPose composed with (mount_x, mount_y, shaft angle);
 *  - maxSensorDistance: the largest float below the length, so that a reading at the full
 *    length is no return (skipped as a point by the likelihood field); the grid draws a ray
 *    as free space without an occupied end when range >= its insertOpts maxDistanceInsertion,
 *    which a grid .ini sets to the whisker length (config/grid-*.ini);
 *  - sensorConeApperture: CONE_APERTURE_DEG (a shaft is a line; zero would give the
 *    likelihood field no point at all). */
class WhiskerRanges
{
   public:
	/** Cone aperture of each ray, degrees: the point MRPT puts at the end of the ray sits
	 *  half of it off the shaft (0.5 mm at 0.6 m). */
	static constexpr double CONE_APERTURE_DEG = 0.1;

	/** The rays of `sweep` in whisker order, labelled `<sensorLabel>_RANGE_<i>`, with the
	 *  sweep's timestamp. Throws core::Error if the sweep does not validate(). */
	static std::vector<mrpt::obs::CObservationRange::Ptr> fromSweep(const CObservationWhiskerContacts& sweep);
};
}  // namespace whiskermap::obs
