#pragma once
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <whiskermap/obs/Shapelet.h>
#include <whiskermap/obs/SweptSector.h>
#include <whiskermap/obs/TSensorNoise.h>
#include <whiskermap/obs/TWhisker.h>

#include <vector>

namespace whiskermap::obs
{
/** One whisking sweep of a whisker array: for every whisker, its mounting and whether and
 *  where it touched (radial distance r, surface normal phi, texture tau; paper section 2).
 *
 *  A real MRPT observation: serializable (versioned), registered with MRPT's class registry
 *  when libwhiskermap-obs is loaded, so rawlogs holding it open in stock tools given the
 *  library as a plugin (`rawlog-edit -p libwhiskermap-obs.so ...`). Whiskers that touched
 *  nothing are kept: they are negative evidence. */
class CObservationWhiskerContacts : public mrpt::obs::CObservation
{
	DEFINE_SERIALIZABLE(CObservationWhiskerContacts, whiskermap::obs)

   public:
	/** Upper bound on whiskers per sweep accepted by validate(); far above any real array. */
	static constexpr size_t MAX_WHISKERS = 1024;
	/** Longest sensor label a stored sweep may hold (printable ASCII). */
	static constexpr size_t MAX_LABEL = 256;

	mrpt::poses::CPose3D sensorPose;  ///< whisker-array frame on the robot (planar: x, y, yaw)
	std::vector<TWhisker> whiskers;  ///< one entry per whisker, touched or not
	TSensorNoise noise;  ///< reading noise std-devs the sensor reports

	/** Throws core::Error naming the whisker and field when a value is not finite, out of
	 *  range (r < 0 or r > length, texture outside [0,1], angle outside the sweep), or the
	 *  whisker count is 0 or above MAX_WHISKERS. Called on load too. */
	void validate() const;

	/** World-frame shapelets of the touched whiskers, for the robot at `robotPose`. */
	std::vector<Shapelet> toShapelets(const mrpt::poses::CPose2D& robotPose) const;

	/** World-frame free space of the sweep (negative evidence): per whisker that moved, the
	 *  sector its shaft swept from sweep_start to its stop (the contact angle, or sweep_end
	 *  when untouched), for the robot at `robotPose`. Fixed whiskers sweep nothing. */
	std::vector<SweptSector> toSweptSectors(const mrpt::poses::CPose2D& robotPose) const;

	/** Number of whiskers that touched something. */
	size_t contactCount() const;

	// See base class docs
	void getSensorPose(mrpt::poses::CPose3D& out) const override { out = sensorPose; }
	void setSensorPose(const mrpt::poses::CPose3D& p) override { sensorPose = p; }
	void getDescriptionAsText(std::ostream& o) const override;
	bool exportTxtSupported() const override { return true; }
	std::string exportTxtHeader() const override;
	std::string exportTxtDataRow() const override;
};
}  // namespace whiskermap::obs
