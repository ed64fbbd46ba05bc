// whisker-export's range outputs read back with MRPT (doc/formats.md, "Whisker sweeps as
// range rays"): same layout, odometry kept, each sweep's rays equal WhiskerRanges'.
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/cli/RangeExport.h>
#include <whiskermap/obs/WhiskerRanges.h>
#include <whiskermap/world/RawlogWriter.h>

#include "../TempDirTest.h"

#include <cmath>

using namespace whiskermap;
using Format = world::RawlogWriter::Format;

namespace
{
class RangeExportTest : public test::TempDirTest
{
   protected:
	/** Three sweeps of two whiskers (one touching at 0.1 + 0.05 k) at poses along x. */
	void writeLog(const std::string& file, Format format)
	{
		world::RawlogWriter w(file, format, world::RawlogWriter::GroundTruth::None);
		for (int k = 0; k < 3; k++)
		{
			obs::CObservationWhiskerContacts s;
			s.timestamp = mrpt::Clock::fromDouble(1300000000 + k);
			s.sensorLabel = "WHISKERS";
			s.sensorPose = mrpt::poses::CPose3D(0.08, 0, 0, 0, 0, 0);
			obs::TWhisker a;
			a.mount_y = 0.03, a.sweep_start = 2.9, a.sweep_end = 0.2, a.length = 0.6;
			a.touched = true, a.angle = 1.0, a.r = 0.1 + 0.05 * k, a.texture = 0.7;
			obs::TWhisker b = a;
			b.mount_y = -0.03, b.sweep_start = -2.9, b.sweep_end = -0.2;
			b.touched = false, b.angle = -0.2, b.r = 0, b.texture = 0;
			s.whiskers = {a, b};
			sweeps.push_back(s);
			poses.emplace_back(0.5 + 0.1 * k, 1.0, 0.1 * k);
			w.write(poses.back(), s);
		}
		w.close();
	}
	static std::vector<mrpt::serialization::CSerializable::Ptr> readAll(const std::string& file)
	{
		mrpt::io::CFileGZInputStream f(file);
		auto arch = mrpt::serialization::archiveFrom(f);
		std::vector<mrpt::serialization::CSerializable::Ptr> out;
		for (;;)
		{
			try
			{
				out.push_back(arch.ReadObject());
			}
			catch (const mrpt::serialization::CExceptionEOF&)
			{
				return out;
			}
		}
	}
	/** `ray` is ray i of sweep k as WhiskerRanges makes it. */
	void expectRay(const mrpt::serialization::CSerializable::Ptr& obj, size_t k, size_t i) const
	{
		const auto ray = std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(obj);
		ASSERT_TRUE(ray) << "sweep " << k << " ray " << i;
		const auto want = obs::WhiskerRanges::fromSweep(sweeps[k])[i];
		EXPECT_EQ(ray->sensorLabel, want->sensorLabel);
		EXPECT_EQ(ray->timestamp, want->timestamp);
		ASSERT_EQ(ray->sensedData.size(), 1u);
		EXPECT_EQ(ray->sensedData[0].sensedDistance, want->sensedData[0].sensedDistance);
		EXPECT_EQ(ray->sensedData[0].sensorPose, want->sensedData[0].sensorPose);
		EXPECT_EQ(ray->maxSensorDistance, want->maxSensorDistance);
	}

	std::vector<obs::CObservationWhiskerContacts> sweeps;
	std::vector<mrpt::poses::CPose2D> poses;
};
}  // namespace

TEST_F(RangeExportTest, ObservationsLayoutKeepsTheOdometryAndPutsTheRaysAfterIt)
{
	writeLog(path("in.rawlog"), Format::Observations);
	EXPECT_EQ(cli::RangeExport::writeRawlog(path("in.rawlog"), path("out.rawlog")), 3u);
	const auto objs = readAll(path("out.rawlog"));
	ASSERT_EQ(objs.size(), 3u * 3u);  // odometry, 2 rays per sweep
	for (size_t k = 0; k < 3; k++)
	{
		const auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(objs[3 * k]);
		ASSERT_TRUE(odo);
		EXPECT_EQ(odo->odometry, poses[k]);
		expectRay(objs[3 * k + 1], k, 0);
		expectRay(objs[3 * k + 2], k, 1);
	}
	EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(objs[1])->sensedData[0].sensedDistance, 0.1f);
	EXPECT_FLOAT_EQ(std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(objs[2])->sensedData[0].sensedDistance, 0.6f);
}

TEST_F(RangeExportTest, ActionSensoryFrameLayoutKeepsTheActionsAndFramesTheRays)
{
	writeLog(path("in.rawlog"), Format::ActionSensoryFrame);
	EXPECT_EQ(cli::RangeExport::writeRawlog(path("in.rawlog"), path("out.rawlog")), 3u);
	const auto in = readAll(path("in.rawlog")), out = readAll(path("out.rawlog"));
	ASSERT_EQ(out.size(), 6u);
	for (size_t k = 0; k < 3; k++)
	{
		const auto a = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(out[2 * k]);
		const auto a0 = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(in[2 * k]);
		ASSERT_TRUE(a && a0);
		const auto mv = a->getBestMovementEstimation(), mv0 = a0->getBestMovementEstimation();
		ASSERT_TRUE(mv && mv0);
		EXPECT_EQ(mv->rawOdometryIncrementReading, mv0->rawOdometryIncrementReading);
		const auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(out[2 * k + 1]);
		ASSERT_TRUE(sf);
		ASSERT_EQ(sf->size(), 2u);
		expectRay(sf->getObservationByIndex(0), k, 0);
		expectRay(sf->getObservationByIndex(1), k, 1);
	}
}

TEST_F(RangeExportTest, SimpleMapHoldsEachSweepsRaysAtItsPose)
{
	writeLog(path("in.rawlog"), Format::ActionSensoryFrame);
	EXPECT_EQ(cli::RangeExport::writeSimpleMap(path("in.rawlog"), path("rays.simplemap")), 3u);
	mrpt::maps::CSimpleMap sm;
	ASSERT_TRUE(sm.loadFromFile(path("rays.simplemap")));
	ASSERT_EQ(sm.size(), 3u);
	for (size_t k = 0; k < 3; k++)
	{
		const auto [pose, sf] = sm.get(k);
		const auto mean = mrpt::poses::CPose2D(pose->getMeanVal());
		EXPECT_NEAR(mean.x(), poses[k].x(), 1e-12);
		EXPECT_NEAR(mean.y(), poses[k].y(), 1e-12);
		EXPECT_NEAR(mean.phi(), poses[k].phi(), 1e-12);
		ASSERT_EQ(sf->size(), 2u);
		expectRay(sf->getObservationByIndex(0), k, 0);
		expectRay(sf->getObservationByIndex(1), k, 1);
	}
}
