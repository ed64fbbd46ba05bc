// whisker-slam's smoothing reads the sweeps from the rawlog after the filter (doc/slam.md,
// "The smoother reads the sweeps after the filter"): the odometry it smooths with is the
// rawlog's, and a rawlog with fewer sweeps than the path is an error naming it.
#include <gtest/gtest.h>
#include <whiskermap/cli/SlamSmoothing.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/RawlogWriter.h>

#include "../TempDirTest.h"

using namespace whiskermap;

namespace
{
class SlamSmoothingTest : public test::TempDirTest
{
   protected:
	/** Four sweeps touching nothing, at odometry poses that turn as they go. */
	std::string writeLog()
	{
		const std::string file = path("four.rawlog");
		world::RawlogWriter w(file, world::RawlogWriter::Format::Observations, world::RawlogWriter::GroundTruth::None);
		for (int k = 0; k < 4; k++)
		{
			obs::CObservationWhiskerContacts s;
			s.timestamp = mrpt::Clock::fromDouble(1300000000 + 0.125 * k);
			s.sensorLabel = "WHISKERS";
			obs::TWhisker a;
			a.mount_y = 0.03, a.sweep_start = 2.9, a.sweep_end = 0.2, a.length = 0.6, a.angle = 1.0;
			s.whiskers = {a};
			odometry.emplace_back(0.5 + 0.05 * k, 1.0 + 0.01 * k * k, 0.1 * k);
			w.write(odometry.back(), s);
		}
		w.close();
		return file;
	}
	static smooth::TSmoothParams onePass()
	{
		smooth::TSmoothParams p;
		p.passes = 1;
		return p;
	}
	std::vector<mrpt::poses::CPose2D> odometry;
};

TEST_F(SlamSmoothingTest, ThePathTouchingNothingIsTheRawlogsOdometry)
{
	const std::string log = writeLog();
	// A wandering estimate: with no contact tied, the most probable path is the odometry's
	// chain from the known start, read from the rawlog.
	std::vector<Eigen::Vector3d> path;
	for (size_t k = 0; k < odometry.size(); k++)
		path.emplace_back(odometry[k].x() + (k ? 0.03 : 0.0), odometry[k].y() - (k ? 0.02 * k : 0.0), odometry[k].phi());
	const auto r = cli::SlamSmoothing(log, slam::TSlamParams()).run(path, {}, onePass(), {});
	ASSERT_EQ(r.path.size(), odometry.size());
	for (size_t k = 0; k < odometry.size(); k++)
	{
		EXPECT_NEAR(r.path[k][0], odometry[k].x(), 1e-6) << "sweep " << k;
		EXPECT_NEAR(r.path[k][1], odometry[k].y(), 1e-6) << "sweep " << k;
		EXPECT_NEAR(r.path[k][2], odometry[k].phi(), 1e-6) << "sweep " << k;
	}
}

TEST_F(SlamSmoothingTest, ARawlogShorterThanThePathIsAnErrorNamingIt)
{
	const std::string log = writeLog();
	const std::vector<Eigen::Vector3d> path(5, Eigen::Vector3d(0.5, 1.0, 0.0));
	try
	{
		cli::SlamSmoothing(log, slam::TSlamParams()).run(path, {}, onePass(), {});
		FAIL() << "no error";
	}
	catch (const core::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find(log + ": 4 sweeps where the filter read 5"), std::string::npos)
			<< e.what();
	}
}
}  // namespace
