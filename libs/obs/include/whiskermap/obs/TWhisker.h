#pragma once

namespace whiskermap::obs
{
/** One whisker of a sweep: its mounting (fixed on the robot) and what it read this time.
 *
 * Angles are in the whisker-array (sensor) frame, which sits at the observation's
 * sensorPose on the robot. During one whisk the whisker, a straight shaft of `length`
 * pivoting at (mount_x, mount_y), protracts from `sweep_start` to `sweep_end` and stops at
 * its first touch (sweep_start == sweep_end: a fixed whisker). */
struct TWhisker
{
	// Mounting (robot geometry)
	double mount_x = 0;  ///< pivot position in the sensor frame, metres
	double mount_y = 0;
	double sweep_start = 0;  ///< shaft angle when the whisk begins, radians
	double sweep_end = 0;  ///< shaft angle when an untouched whisk ends, radians
	double length = 0;  ///< shaft length, metres (> 0)

	// Reading
	bool touched = false;  ///< false: the whisk ended without contact (negative evidence)
	double angle = 0;  ///< shaft angle at the contact (or sweep_end), from the actuator
	double r = 0;  ///< contact distance from the pivot along the shaft, in [0, length]
	double normal = 0;  ///< outward surface-normal angle of the touched surface, radians
	double texture = 0;  ///< texture of the touched surface, in [0, 1]
};
}  // namespace whiskermap::obs
