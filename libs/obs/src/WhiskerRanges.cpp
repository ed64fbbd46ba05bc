#include <mrpt/core/bits_math.h>
#include <mrpt/poses/CPose3D.h>
#include <whiskermap/obs/WhiskerRanges.h>

#include <cmath>
#include <string>

namespace whiskermap::obs
{
std::vector<mrpt::obs::CObservationRange::Ptr> WhiskerRanges::fromSweep(const CObservationWhiskerContacts& sweep)
{
	sweep.validate();
	std::vector<mrpt::obs::CObservationRange::Ptr> out;
	out.reserve(sweep.whiskers.size());
	for (size_t i = 0; i < sweep.whiskers.size(); ++i)
	{
		const TWhisker& w = sweep.whiskers[i];
		auto ray = std::make_shared<mrpt::obs::CObservationRange>();
		ray->timestamp = sweep.timestamp;
		ray->sensorLabel = sweep.sensorLabel + "_RANGE_" + std::to_string(i);
		ray->minSensorDistance = 0;
		ray->maxSensorDistance = std::nextafter(static_cast<float>(w.length), 0.0f);
		ray->sensorConeApperture = static_cast<float>(mrpt::DEG2RAD(CONE_APERTURE_DEG));
		mrpt::obs::CObservationRange::TMeasurement m;
		m.sensorID = static_cast<uint16_t>(i);
		// `angle` is the shaft angle at the contact, or sweep_end when the whisk touched nothing
		const mrpt::poses::CPose3D base = sweep.sensorPose + mrpt::poses::CPose3D(w.mount_x, w.mount_y, 0, w.angle, 0, 0);
		m.sensorPose = base.asTPose();
		m.sensedDistance = static_cast<float>(w.touched ? w.r : w.length);
		ray->sensedData.push_back(m);
		out.push_back(std::move(ray));
	}
	return out;
}
}  // namespace whiskermap::obs
