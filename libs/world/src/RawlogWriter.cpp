#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/PathLog.h>
#include <whiskermap/world/RawlogWriter.h>

#include <cstdio>
#include <filesystem>

namespace whiskermap::world
{
namespace fs = std::filesystem;

std::string RawlogWriter::groundTruthPathFile(const std::string& rawlogPath)
{
	const fs::path p(rawlogPath);
	return (p.parent_path() / (p.stem().string() + "_ground_truth_robot_path.txt")).string();
}

RawlogWriter::RawlogWriter(const std::string& rawlogPath, Format format, GroundTruth groundTruth)
	: m_path(rawlogPath),
	  m_gtPath(groundTruth == GroundTruth::Write ? groundTruthPathFile(rawlogPath) : ""),
	  m_format(format)
{
	if (!m_out.open(m_path + ".tmp"))
		throw core::Error(m_path + ": cannot create file (does its folder exist?)");
	if (m_gtPath.empty()) return;
	m_gt.open(m_gtPath + ".tmp");
	if (!m_gt) throw core::Error(m_gtPath + ": cannot create file");
	m_gt << PathLog::header("Ground truth robot path, one line per whisker sweep in the rawlog");
}

RawlogWriter::~RawlogWriter()
{
	if (m_closed) return;
	m_out.close();
	m_gt.close();
	std::error_code ec;
	fs::remove(m_path + ".tmp", ec);
	if (!m_gtPath.empty()) fs::remove(m_gtPath + ".tmp", ec);
}

void RawlogWriter::write(
	const mrpt::poses::CPose2D& pose, const obs::CObservationWhiskerContacts& sweep)
{
	write(pose, pose, sweep);
}

void RawlogWriter::write(
	const mrpt::poses::CPose2D& pose, const mrpt::poses::CPose2D& truth,
	const obs::CObservationWhiskerContacts& sweep)
{
	sweep.validate();  // nothing invalid is ever written
	auto arch = mrpt::serialization::archiveFrom(m_out);
	if (m_format == Format::Observations)
	{
		mrpt::obs::CObservationOdometry odo;
		odo.timestamp = sweep.timestamp;
		odo.sensorLabel = "ODOMETRY";
		odo.odometry = pose;
		arch << odo << sweep;
	}
	else
	{
		mrpt::obs::CActionRobotMovement2D mv;
		mv.timestamp = sweep.timestamp;
		const auto increment = pose - (m_last ? *m_last : mrpt::poses::CPose2D());
		mv.computeFromOdometry(
			increment, m_motionModel ? m_motionModel(increment)
									 : mrpt::obs::CActionRobotMovement2D::TMotionModelOptions());
		mrpt::obs::CActionCollection acts;
		acts.insert(mv);
		mrpt::obs::CSensoryFrame sf;
		sf.insert(std::make_shared<obs::CObservationWhiskerContacts>(sweep));
		arch << acts << sf;
	}
	m_last = pose;
	if (m_gtPath.empty()) return;
	m_gt << PathLog::line(mrpt::Clock::toDouble(sweep.timestamp), truth);
}

void RawlogWriter::close()
{
	m_out.close();
	m_gt.close();
	if (!m_gtPath.empty() && !m_gt) throw core::Error(m_gtPath + ": write failed");
	fs::rename(m_path + ".tmp", m_path);
	if (!m_gtPath.empty()) fs::rename(m_gtPath + ".tmp", m_gtPath);
	m_closed = true;
}
}  // namespace whiskermap::world
