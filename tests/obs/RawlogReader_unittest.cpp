#include <gtest/gtest.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/RawlogWriter.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <filesystem>
#include <fstream>

using namespace whiskermap;
namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

class RawlogReaderTest : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		dir = fs::temp_directory_path() /
			  ("whiskermap_reader_" + std::to_string(::getpid()) + "_" +
			   ::testing::UnitTest::GetInstance()->current_test_info()->name());
		fs::create_directories(dir);
	}
	void TearDown() override { fs::remove_all(dir); }

	/** Simulates `n` grid poses of the paper arena into a rawlog of the given format. */
	std::string simulate(world::RawlogWriter::Format fmt, size_t n, const std::string& name)
	{
		const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
		const auto robot = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
		world::WhiskerSimulator sim(w, robot, {0.01, 0.05, 0.05}, 7);
		const auto path = (dir / name).string();
		world::RawlogWriter out(path, fmt);
		const auto poses = world::Trajectory::paperGrid(w);
		for (size_t i = 0; i < n; i++)
		{
			const auto sweep = sim.sense(poses[i], mrpt::Clock::fromDouble(1e9 + i));
			out.write(poses[i], *sweep);
			truth.push_back(poses[i]);
		}
		out.close();
		return path;
	}

	std::string errorOf(const std::string& path)
	{
		try
		{
			obs::RawlogReader::read(path);
		}
		catch (const core::Error& e)
		{
			return e.what();
		}
		return "";
	}

	fs::path dir;
	std::vector<mrpt::poses::CPose2D> truth;
};
}  // namespace

TEST_F(RawlogReaderTest, ReadsBothFormatsWithTheirPoses)
{
	const auto a = obs::RawlogReader::read(simulate(world::RawlogWriter::Format::Observations, 20, "a.rawlog"));
	const auto b = obs::RawlogReader::read(simulate(world::RawlogWriter::Format::ActionSensoryFrame, 20, "b.rawlog"));
	EXPECT_FALSE(a.actionSensoryFrameFormat);
	EXPECT_TRUE(b.actionSensoryFrameFormat);
	EXPECT_EQ(a.objects, 40u);
	EXPECT_EQ(b.objects, 40u);
	ASSERT_EQ(a.sweeps.size(), 20u);
	ASSERT_EQ(b.sweeps.size(), 20u);
	for (size_t i = 0; i < 20; i++)
	{
		// Observations carry absolute poses; actions carry increments composed from the origin.
		EXPECT_NEAR((a.sweeps[i].robotPose - truth[i]).norm(), 0, 1e-12);
		EXPECT_NEAR((b.sweeps[i].robotPose - truth[i]).norm(), 0, 1e-9);
		EXPECT_NEAR(std::abs(b.sweeps[i].robotPose.phi() - truth[i].phi()), 0, 1e-9);
		EXPECT_EQ(a.sweeps[i].obs->contactCount(), b.sweeps[i].obs->contactCount());
	}
}

TEST_F(RawlogReaderTest, MissingEmptyAndNonRawlogFilesAreErrors)
{
	EXPECT_EQ(errorOf((dir / "nope.rawlog").string()), (dir / "nope.rawlog").string() + ": no such file");
	std::ofstream((dir / "empty.rawlog").string()).close();
	EXPECT_NE(errorOf((dir / "empty.rawlog").string()).find("empty file"), std::string::npos);
	std::ofstream((dir / "text.rawlog").string()) << "this is not a rawlog at all\n";
	EXPECT_NE(errorOf((dir / "text.rawlog").string()).find("corrupt rawlog at object #0"), std::string::npos);
}

TEST_F(RawlogReaderTest, TruncatedFileIsAnError)
{
	const auto path = simulate(world::RawlogWriter::Format::Observations, 40, "t.rawlog");
	const auto size = fs::file_size(path);
	for (auto keep : {size / 3, size / 2, size - 9})
	{
		const auto cut = (dir / ("cut" + std::to_string(keep) + ".rawlog")).string();
		fs::copy_file(path, cut);
		fs::resize_file(cut, keep);
		const auto e = errorOf(cut);
		EXPECT_EQ(e.rfind(cut + ": ", 0), 0u) << e;  // names the file
		EXPECT_NE(e.find("truncated"), std::string::npos) << e;
		EXPECT_EQ(e.find('\n'), std::string::npos) << "one line: " << e;
	}
}

TEST_F(RawlogReaderTest, CorruptedBytesAreAnError)
{
	const auto path = simulate(world::RawlogWriter::Format::Observations, 40, "c.rawlog");
	std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
	f.seekp(static_cast<std::streamoff>(fs::file_size(path) / 2));
	const char junk[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
	f.write(junk, sizeof(junk));
	f.close();
	const auto e = errorOf(path);
	EXPECT_EQ(e.rfind(path + ": ", 0), 0u) << e;
	EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST_F(RawlogReaderTest, NanReadingIsAnErrorNamingTheObject)
{
	// A sweep holding NaN, written as a raw object after an odometry entry.
	const auto path = (dir / "nan.rawlog").string();
	{
		obs::CObservationWhiskerContacts o;
		o.sensorLabel = "WHISKERS";
		obs::TWhisker w;
		w.length = 0.5;
		w.touched = true;
		w.r = std::nan("");
		o.whiskers = {w};
		mrpt::io::CFileGZOutputStream f(path);
		mrpt::serialization::archiveFrom(f) << o;
	}
	const auto e = errorOf(path);
	EXPECT_NE(e.find("corrupt rawlog at object #0"), std::string::npos) << e;
	EXPECT_NE(e.find("non-finite"), std::string::npos) << e;
}

TEST_F(RawlogReaderTest, SweepWithoutPoseIsAnError)
{
	const auto path = (dir / "nopose.rawlog").string();
	{
		obs::CObservationWhiskerContacts o;
		obs::TWhisker w;
		w.length = 0.5;
		o.whiskers = {w};
		mrpt::io::CFileGZOutputStream f(path);
		mrpt::serialization::archiveFrom(f) << o;
	}
	EXPECT_NE(errorOf(path).find("has no robot pose before it"), std::string::npos);
}
