#pragma once
#include <mrpt/poses/CPose3D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <cmath>

namespace whiskermap::test
{
/** A hand-made sweep of two whiskers mounted at (mountX, +-mountY) in the sensor frame:
 *  whisker 0 touched 0.25 m along its shaft, pointing left; whisker 1 touched nothing and
 *  ended its whisk pointing 0.2 rad right of forward. */
inline obs::CObservationWhiskerContacts sampleSweep(double mountX, double mountY)
{
	obs::CObservationWhiskerContacts o;
	o.timestamp = mrpt::Clock::fromDouble(1300000000.5);
	o.sensorLabel = "WHISKERS";
	o.sensorPose = mrpt::poses::CPose3D(0.08, 0, 0, 0, 0, 0);
	o.noise = {0.01, 0.0872664626, 0.05};
	obs::TWhisker a;
	a.mount_x = mountX;
	a.mount_y = mountY;
	a.sweep_start = 2.9;
	a.sweep_end = 0.2;
	a.length = 0.6;
	a.touched = true;
	a.angle = M_PI / 2;
	a.r = 0.25;
	a.normal = -M_PI / 2;
	a.texture = 0.7;
	obs::TWhisker b = a;
	b.mount_y = -mountY;
	b.sweep_start = -2.9;
	b.sweep_end = -0.2;
	b.touched = false;
	b.angle = -0.2;
	b.r = b.normal = b.texture = 0;
	o.whiskers = {a, b};
	return o;
}
}  // namespace whiskermap::test
