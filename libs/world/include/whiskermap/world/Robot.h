#pragma once
#include <mrpt/poses/CPose3D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/obs/TWhisker.h>

#include <string>
#include <vector>

namespace whiskermap::world
{
/** A whiskered robot's geometry: its round body and its whisker array (mountings only).
 *  Read from a robot .ini (config/robots/, format in doc/formats.md). */
struct Robot
{
	double radius = 0.1;  ///< body radius, metres
	mrpt::poses::CPose3D sensorPose;  ///< whisker-array frame on the robot (x, y, yaw)
	std::vector<obs::TWhisker> whiskers;  ///< mountings; reading fields unused

	static Robot load(const std::string& path);

	/** A sweep (label WHISKERS) in which no whisker touched anything: this robot's sensor
	 *  pose and mountings, and the readings an untouched whisker carries (angle = sweep_end,
	 *  r = normal = texture = 0). The simulator and the contact-log reader fill in contacts. */
	obs::CObservationWhiskerContacts::Ptr blankSweep(
		const obs::TSensorNoise& noise, mrpt::Clock::time_point stamp) const;
};
}  // namespace whiskermap::world
