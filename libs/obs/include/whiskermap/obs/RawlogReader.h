#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <functional>
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
		size_t sweepCount = 0;  ///< whisker sweeps read
		bool actionSensoryFrameFormat = false;  ///< true for the CActionCollection format
	};

	/** Reads the whole rawlog into memory. */
	static Contents read(const std::string& path);

	/** Streams the rawlog: calls `onSweep` for each sweep in order, holding one object in
	 *  memory at a time. Returns the counts (its `sweeps` stay empty). The file is verified
	 *  end to end before the first sweep is delivered, so a damaged file fails before any
	 *  work is done. */
	static Contents forEach(const std::string& path, const std::function<void(const Sweep&)>& onSweep);
};
}  // namespace whiskermap::obs
