#pragma once
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <fstream>
#include <functional>
#include <optional>
#include <string>

namespace whiskermap::world
{
/** Writes whisker sweeps with their robot poses as an MRPT rawlog, plus (unless told not to)
 *  MRPT-simulator style ground truth `<name>_ground_truth_robot_path.txt` beside it.
 *
 *  Formats: Observations writes a CObservationOdometry (the absolute pose) before each sweep;
 *  ActionSensoryFrame writes, per sweep, a CActionCollection holding a CActionRobotMovement2D
 *  (the pose increment from the previous pose; from the origin for the first) and a
 *  CSensoryFrame holding the sweep, as stock rbpf-slam needs; the action carries the motion
 *  model set by setMotionModel (MRPT's default Gaussian model unless told otherwise).
 *
 *  Files are written under temporary names and renamed by close(): a run that fails midway
 *  leaves no half-written rawlog behind. */
class RawlogWriter
{
   public:
	enum class Format
	{
		Observations,
		ActionSensoryFrame
	};

	/** Write: the poses are the truth (a simulation), recorded beside the rawlog; None: they
	 *  are only odometry (an imported log), nothing is written beside it. */
	enum class GroundTruth
	{
		Write,
		None
	};

	RawlogWriter(
		const std::string& rawlogPath, Format format, GroundTruth groundTruth = GroundTruth::Write);
	~RawlogWriter();  ///< removes the temporary files if close() was not reached

	/** Appends a sweep (validated first: throws core::Error on a bad value) taken at `pose`,
	 *  both the recorded odometry and the truth. */
	void write(const mrpt::poses::CPose2D& pose, const obs::CObservationWhiskerContacts& sweep);
	/** The same with odometry that differs from the truth: the rawlog records `odometry`,
	 *  the ground-truth file `truth`. */
	void write(
		const mrpt::poses::CPose2D& odometry, const mrpt::poses::CPose2D& truth,
		const obs::CObservationWhiskerContacts& sweep);
	/** The motion model of each action written from now on (action-sf layout), given the
	 *  odometry increment it records; MRPT's default model unless set. */
	using MotionModel =
		std::function<mrpt::obs::CActionRobotMovement2D::TMotionModelOptions(const mrpt::poses::CPose2D& increment)>;
	void setMotionModel(MotionModel model) { m_motionModel = std::move(model); }
	/** Flushes and renames both files into place. */
	void close();

	/** "<dir>/<stem>_ground_truth_robot_path.txt" for a rawlog path. */
	static std::string groundTruthPathFile(const std::string& rawlogPath);

   private:
	std::string m_path, m_gtPath;
	Format m_format;
	mrpt::io::CFileGZOutputStream m_out;
	std::ofstream m_gt;
	std::optional<mrpt::poses::CPose2D> m_last;
	MotionModel m_motionModel;
	bool m_closed = false;
};
}  // namespace whiskermap::world
