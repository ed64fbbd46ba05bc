#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/ByteSource.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/obs/RawlogScanner.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace whiskermap::obs
{
/** Reads the whisker sweeps of a rawlog, with the robot pose of each, from either format:
 *  - observations-only: CObservationOdometry entries give the absolute robot pose for the
 *    CObservationWhiskerContacts that follow them;
 *  - actions/sensory frames: CActionRobotMovement2D raw odometry increments are composed
 *    from the origin and give the pose of the sensory frame that follows.
 *
 *  Trusts nothing (doc/formats.md, "What the reader checks"): the constructor reads the
 *  whole file once with RawlogScanner, which checks every byte before a deserializer sees
 *  it, and deserializes each sweep (which validates its values), so a damaged file fails
 *  before any work is done; next() then reads it again, one object in memory at a time.
 *  Errors are core::Error with one line naming the file. */
class RawlogReader
{
   public:
	/** One sweep and where the robot was. */
	struct Sweep
	{
		mrpt::poses::CPose2D robotPose;
		CObservationWhiskerContacts::Ptr obs;
	};

	/** What the whole file holds (known after the constructor). */
	struct Summary
	{
		size_t objects = 0;  ///< top-level objects (actions, frames, observations)
		size_t sweepCount = 0;  ///< whisker sweeps
		bool actionSensoryFrameFormat = false;  ///< true for the CActionCollection format
		double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  ///< bounding box of the sweeps' robot positions
		double maxSigmaR = 0;  ///< largest sigma_r any sweep reports
		double maxReach = 0;  ///< largest whisker reach from the robot centre (mount + length)
	};

	/** What a rawlog holds (the static helpers' result). */
	struct Contents : Summary
	{
		std::vector<Sweep> sweeps;  ///< read(): every sweep; forEach(): empty
	};

	/** Opens and checks `path` end to end (throws core::Error). */
	explicit RawlogReader(const std::string& path);
	/** The same over any byte source: `open` is called once per pass (tests, fuzzing). */
	RawlogReader(std::function<std::unique_ptr<ByteSource>()> open, std::string label);

	const Summary& summary() const { return m_summary; }
	/** The next sweep in order; false after the last. */
	bool next(Sweep& out);

	/** Reads the whole rawlog into memory (memory grows with the log: tests and small logs). */
	static Contents read(const std::string& path);
	/** Streams the rawlog: `onSweep` for each sweep in order, after the whole file was checked. */
	static Contents forEach(const std::string& path, const std::function<void(const Sweep&)>& onSweep);

   private:
	/** Reads objects until a sweep is found (true) or the data ends (false). */
	bool advance(Sweep& out);

	std::function<std::unique_ptr<ByteSource>()> m_open;
	std::string m_label;
	Summary m_summary;
	std::unique_ptr<ByteSource> m_src;
	std::unique_ptr<RawlogScanner> m_scan;
	RawlogScanner::Object m_obj;
	size_t m_item = 0;
	std::optional<mrpt::poses::CPose2D> m_pose;
	bool m_anyIncrement = false;
};
}  // namespace whiskermap::obs
