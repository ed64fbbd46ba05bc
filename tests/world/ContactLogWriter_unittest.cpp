#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/ContactLogReader.h>
#include <whiskermap/world/ContactLogWriter.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "../TempDirTest.h"

using namespace whiskermap;
using world::ContactLogWriter;
namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

class ContactLogWriterTest : public test::TempDirTest
{
   protected:
	void SetUp() override
	{
		TempDirTest::SetUp();
		robot = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
		world = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	}

	world::Robot robot;
	world::World world;
	const obs::TSensorNoise noise{0.01, 0.05, 0.05};
};

bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST_F(ContactLogWriterTest, WhatItWritesReadsBackBitForBit)
{
	world::WhiskerSimulator sim(world, robot, noise, 5);
	const auto path = (dir / "log.csv").string();
	std::vector<std::pair<mrpt::poses::CPose2D, obs::CObservationWhiskerContacts::Ptr>> in;
	{
		ContactLogWriter w(path, "a test");
		double t = 1e9;
		for (const auto& p : world::Trajectory::paperGrid(world, 6))
		{
			if (!sim.poseIsFree(p)) continue;
			const mrpt::poses::CPose2D q(p.x() + 1e-3 / 3, p.y() - 1e-7 / 7, p.phi() + 0.1);
			in.emplace_back(q, sim.sense(q, mrpt::Clock::fromDouble(t += 0.0123457)));
			w.write(q, *in.back().second);
		}
		w.close();
		EXPECT_EQ(w.sweeps(), in.size());
		EXPECT_EQ(w.rows(), 6 * in.size());
	}
	world::ContactLogReader r(path, robot, noise);
	size_t k = 0;
	for (world::ContactLogReader::Sweep s; r.next(s); k++)
	{
		ASSERT_LT(k, in.size());
		EXPECT_TRUE(same(s.odometry.x(), in[k].first.x()));
		EXPECT_TRUE(same(s.odometry.y(), in[k].first.y()));
		EXPECT_TRUE(same(s.odometry.phi(), in[k].first.phi()));
		EXPECT_EQ(s.obs->timestamp, in[k].second->timestamp);
		for (size_t i = 0; i < 6; i++)
		{
			const auto &a = s.obs->whiskers[i], &b = in[k].second->whiskers[i];
			EXPECT_EQ(a.touched, b.touched);
			EXPECT_TRUE(
				same(a.angle, b.angle) && same(a.r, b.r) && same(a.normal, b.normal) &&
				same(a.texture, b.texture))
				<< "sweep " << k << " whisker " << i;
		}
	}
	EXPECT_EQ(k, in.size());
	EXPECT_GT(k, 100u);
}

TEST_F(ContactLogWriterTest, OneSensorPerLogAndTimeInOrder)
{
	const auto path = (dir / "log.csv").string();
	const auto first = robot.blankSweep(noise, mrpt::Clock::fromDouble(10));
	auto expectRefused =
		[&](const obs::CObservationWhiskerContacts& second, const std::string& what)
	{
		ContactLogWriter w(path, "src.rawlog");
		w.write({}, *first);
		try
		{
			w.write({}, second);
			ADD_FAILURE() << "accepted " << what;
		}
		catch (const core::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find("src.rawlog: sweep 1: " + what), std::string::npos)
				<< e.what();
		}
	};
	auto other = *first;
	other.noise.sigma_r = 0.02;
	expectRefused(other, "the noise differs");
	other = *first;
	other.whiskers[3].length = 0.5;
	expectRefused(other, "whisker 3's mounting differs");
	other = *first;
	other.whiskers.pop_back();
	expectRefused(other, "the whisker count differs");
	other = *first;
	other.sensorPose = mrpt::poses::CPose3D(0.1, 0, 0, 0, 0, 0);
	expectRefused(other, "the sensor pose differs");
	other = *first;
	other.timestamp = mrpt::Clock::fromDouble(9);
	expectRefused(other, "time goes backwards");
	EXPECT_FALSE(fs::exists(path));
	EXPECT_FALSE(fs::exists(path + ".tmp"));  // removed by the destructor
}

TEST_F(ContactLogWriterTest, NothingToWriteIsAnError)
{
	const auto path = (dir / "log.csv").string();
	ContactLogWriter w(path, "empty.rawlog");
	EXPECT_THROW(w.close(), core::Error);
	EXPECT_THROW(ContactLogWriter((dir / "no" / "such" / "x.csv").string(), "x"), core::Error);
}

TEST_F(ContactLogWriterTest, HeaderListsTheSensorForTheImport)
{
	const auto path = (dir / "log.csv").string();
	ContactLogWriter w(path, "src.rawlog");
	w.write({}, *robot.blankSweep(noise, mrpt::Clock::fromDouble(1)));
	w.close();
	std::ifstream f(path);
	std::string line;
	std::getline(f, line);
	EXPECT_EQ(line, "# whiskermap contacts v1");
	std::string all((std::istreambuf_iterator<char>(f)), {});
	EXPECT_NE(
		all.find("# noise (for whisker-import --noise): sigma_r=0.01 m, sigma_phi_deg=2.86479"),
		std::string::npos)
		<< all;
	EXPECT_NE(all.find("#   3: 0, -0.03, -170, -10, 0.6\n"), std::string::npos) << all;
	EXPECT_NE(
		all.find("\ntime,odom_x,odom_y,odom_yaw_deg,whisker,touched,angle_deg,r,normal_deg,"
				 "texture\n1,0,0,0,0,0,10,0,0,0\n"),
		std::string::npos)
		<< all;
}
