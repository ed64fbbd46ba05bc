#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <string>
#include <vector>

namespace whiskermap::obs
{
/** Reads the whisker sweeps of a rawlog, with the robot pose of each, from either format:
 *  - observations-only: CObservationOdometry entries give the absolute robot pose for the
 *    CObservationWhiskerContacts that follow them;
 *  - actions/sensory frames: CActionRobotMovement2D increments are composed from the origin
 *    and give the pose of the sensory frame that follows.
 *  Other observation classes are counted and skipped.
 *
 *  Bad input throws core::Error with one line naming the file: missing file, a gzip stream
 *  that is truncated or corrupt, an object that cannot be deserialized (unknown class,
 *  cut off, bad values such as NaN), a whisker sweep with no pose before it. */
class RawlogReader
{
   public:
	/** One sweep and where the robot was. */
	struct Sweep
	{
		mrpt::poses::CPose2D robotPose;
		CObservationWhiskerContacts::Ptr obs;
	};

	/** What a rawlog holds. */
	struct Contents
	{
		std::vector<Sweep> sweeps;
		size_t objects = 0;  ///< top-level objects read (actions, frames, observations)
		bool actionSensoryFrameFormat = false;  ///< true for the CActionCollection format
	};

	static Contents read(const std::string& path);
};
}  // namespace whiskermap::obs
