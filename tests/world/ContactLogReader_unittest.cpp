#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/ContactLogReader.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/World.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "../TempDirTest.h"

using namespace whiskermap;
using world::ContactLogReader;
namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
const std::string HAND_LOG = SRC + "/tests/data/contact_logs/one_table.csv";

world::Robot scratchbot() { return world::Robot::load(SRC + "/config/robots/scratchbot.ini"); }

std::vector<ContactLogReader::Sweep> readAll(const std::string& path)
{
	ContactLogReader r(path, scratchbot(), world::NoisePreset::load("default"));
	std::vector<ContactLogReader::Sweep> out;
	for (ContactLogReader::Sweep s; r.next(s);) out.push_back(s);
	EXPECT_EQ(r.sweeps(), out.size());
	return out;
}

class ContactLogReaderTest : public test::TempDirTest
{
   protected:
	std::string file(const std::string& text)
	{
		const auto p = (dir / "log.csv").string();
		std::ofstream(p, std::ios::binary) << text;
		return p;
	}
	/** The error message reading `text` gives, without the file name. */
	std::string error(const std::string& text)
	{
		const auto p = file(text);
		try
		{
			readAll(p);
		}
		catch (const core::Error& e)
		{
			const std::string m = e.what();
			EXPECT_EQ(m.rfind(p + ": ", 0), 0u) << m;
			return m.substr(p.size() + 2);
		}
		ADD_FAILURE() << "no error";
		return "";
	}
};

const std::string HEAD =
	"# whiskermap contacts v1\n"
	"time,odom_x,odom_y,odom_yaw_deg,whisker,touched,angle_deg,r,normal_deg,texture\n";
/** One sweep of six whiskers at time `t`, whisker 2 touching. */
std::string sweep(const std::string& t)
{
	std::string s;
	for (int i = 0; i < 6; i++)
		s +=
			t + ",1,2,90," + std::to_string(i) + (i == 2 ? ",1,100,0.3,-45,0.7\n" : ",0,0,0,0,0\n");
	return s;
}
}  // namespace

TEST(ContactLogReader, ReadsTheHandWrittenLogAsWritten)
{
	const auto sweeps = readAll(HAND_LOG);
	ASSERT_EQ(sweeps.size(), 4u);
	const auto robot = scratchbot();
	const auto noise = world::NoisePreset::load("default");
	const double times[] = {0, 0.5, 1.0, 1.5};
	const mrpt::poses::CPose2D poses[] = {
		{1.5, 1.5, 0}, {1.5, 2.05, M_PI}, {1.5, 0.95, 0}, {2.5, 1.5, M_PI / 2}};
	for (size_t k = 0; k < 4; k++)
	{
		const auto& o = *sweeps[k].obs;
		EXPECT_EQ(o.timestamp, mrpt::Clock::fromDouble(times[k]));
		EXPECT_NEAR((sweeps[k].odometry - poses[k]).norm(), 0, 1e-15);
		EXPECT_NEAR(std::abs(core::wrapToPi(sweeps[k].odometry.phi() - poses[k].phi())), 0, 1e-15);
		EXPECT_EQ(o.sensorLabel, "WHISKERS");
		EXPECT_EQ(o.sensorPose, robot.sensorPose);
		EXPECT_EQ(o.noise.sigma_r, noise.sigma_r);
		EXPECT_EQ(o.noise.sigma_phi, noise.sigma_phi);
		ASSERT_EQ(o.whiskers.size(), 6u);
		for (size_t i = 0; i < 6; i++)
		{
			EXPECT_EQ(o.whiskers[i].mount_x, robot.whiskers[i].mount_x);
			EXPECT_EQ(o.whiskers[i].sweep_start, robot.whiskers[i].sweep_start);
			EXPECT_EQ(o.whiskers[i].length, robot.whiskers[i].length);
		}
	}
	EXPECT_EQ(sweeps[0].line, 10u);
	EXPECT_EQ(sweeps[3].line, 33u);
	// Values as written (line 10: whisker 0, 36.8 deg, 0.493 m, normal 90 deg, texture 0.70).
	const auto& w0 = sweeps[0].obs->whiskers[0];
	EXPECT_TRUE(w0.touched);
	EXPECT_NEAR(w0.angle, core::deg2rad(36.8), 1e-15);
	EXPECT_EQ(w0.r, 0.493);
	EXPECT_NEAR(w0.normal, M_PI / 2, 1e-15);
	EXPECT_EQ(w0.texture, 0.7);
	// Rows in any order (sweep 2 lists whisker 2 first); untouched whiskers whatever their
	// text ("-10,0,0,0", empty, "0,0,0,0") carry the blank readings.
	EXPECT_EQ(sweeps[2].obs->whiskers[2].r, 0.572);
	EXPECT_EQ(sweeps[2].obs->whiskers[0].r, 0.6);
	for (size_t k : {1, 2})
		for (size_t i : {3, 4, 5})
		{
			const auto& w = sweeps[k].obs->whiskers[i];
			EXPECT_FALSE(w.touched);
			EXPECT_EQ(w.angle, w.sweep_end);
			EXPECT_EQ(w.r, 0);
			EXPECT_EQ(w.normal, 0);
			EXPECT_EQ(w.texture, 0);
		}
	EXPECT_EQ(sweeps[0].obs->contactCount() + sweeps[1].obs->contactCount(), 9u);
}

TEST(ContactLogReader, HandWrittenContactsLieOnTheTablesLegsAndTheWall)
{
	// What the contacts imply: every table-textured contact is on a leg of the one table,
	// three legs or more are touched, and the rough ones are on the wall at x = 3.
	const auto w = world::World::load(SRC + "/tests/data/contact_logs/one_table_world.ini");
	ASSERT_EQ(w.tables.size(), 1u);
	std::vector<Eigen::Vector2d> legs;
	for (int k = 0; k < 4; k++) legs.push_back(w.tables[0].legCentre(k));
	std::set<size_t> touched;
	size_t onWall = 0;
	for (const auto& s : readAll(HAND_LOG))
		for (const auto& c : s.obs->toShapelets(s.odometry))
		{
			if (c.texture < 0.5)
			{
				EXPECT_NEAR(c.x, 3.0, 0.01);
				onWall++;
				continue;
			}
			size_t nearest = 0;
			for (size_t l = 1; l < legs.size(); l++)
				if ((legs[l] - Eigen::Vector2d(c.x, c.y)).norm() <
					(legs[nearest] - Eigen::Vector2d(c.x, c.y)).norm())
					nearest = l;
			const Eigen::Vector2d d = legs[nearest] - Eigen::Vector2d(c.x, c.y);
			EXPECT_LT(d.lpNorm<Eigen::Infinity>(), 0.025 + 0.01) << c.x << ", " << c.y;
			touched.insert(nearest);
		}
	EXPECT_GE(touched.size(), 3u);
	EXPECT_EQ(onWall, 3u);
}

TEST_F(ContactLogReaderTest, ColumnsInAnyOrderCommentsAnywhereAndWindowsLineEnds)
{
	std::string text =
		"\xEF\xBB\xBF# whiskermap contacts v1\r\n# a comment\r\n\r\n"
		" texture , r,normal_deg,angle_deg,touched,whisker,odom_yaw_deg,odom_y,odom_x,time\r\n";
	for (int i = 5; i >= 0; i--)
		text += i == 2 ? "0.7,0.3,-45,100,1,2,90,2,1,7\r\n# between rows\r\n"
					   : "x,,nan,,0," + std::to_string(i) + ",90,2,1,7\r\n";
	const auto s = readAll(file(text));
	const auto reference = readAll(file(HEAD + sweep("7")));
	ASSERT_EQ(s.size(), 1u);
	EXPECT_EQ(s[0].line, 5u);
	EXPECT_EQ(s[0].obs->timestamp, reference[0].obs->timestamp);
	EXPECT_EQ(s[0].odometry, reference[0].odometry);
	for (size_t i = 0; i < 6; i++)
	{
		const auto &a = s[0].obs->whiskers[i], &b = reference[0].obs->whiskers[i];
		EXPECT_EQ(a.touched, b.touched);
		EXPECT_EQ(a.angle, b.angle);
		EXPECT_EQ(a.r, b.r);
		EXPECT_EQ(a.normal, b.normal);
		EXPECT_EQ(a.texture, b.texture);
	}
}

TEST_F(ContactLogReaderTest, SweepsMayShareATimeButNotGoBack)
{
	EXPECT_EQ(readAll(file(HEAD + sweep("1") + sweep("1") + sweep("2"))).size(), 3u);
	EXPECT_EQ(
		error(HEAD + sweep("2") + sweep("1.9999999")),
		"line 9, column 'time' (field 1): time goes backwards: '1.9999999' is before the "
		"previous sweep's (line 3)");
}

TEST_F(ContactLogReaderTest, ErrorsNameLineAndColumn)
{
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,0,1,100,0.3,-45,0.7,extra\n"),
		"line 3, field 11: extra value 'extra': the header has 10 columns");
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,9,0,0,0,0,0\n"),
		"line 3, column 'whisker' (field 5): whisker 9 is not one of the robot's 6 (0..5)");
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,-1,0,0,0,0,0\n"),
		"line 3, column 'whisker' (field 5): '-1' is not a whisker index (0, 1, 2, ...)");
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,2,1,100,0.3,-45,inf\n"),
		"line 3, column 'texture' (field 10): 'inf' is not finite");
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,2,1,9,0.3,-45,0.5\n"),
		"line 3, column 'angle_deg' (field 7): '9' deg is outside whisker 2's sweep [10, 170] deg");
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,0,1,100,0.3,-45\n"),
		"line 3, column 'texture' (field 10): missing value: the row has 9 fields, the header 10");
	EXPECT_EQ(
		error(HEAD + "0,1,2,90,0,1,100,0.3,-45,0.7\n0,1,2.5,90,1,0,0,0,0,0\n"),
		"line 4, column 'odom_y' (field 3): '2.5' differs from the sweep starting at line 3, which "
		"still lacks whiskers 1, 2, 3, 4, 5 (the rows of a sweep share time and odometry, one "
		"row per whisker)");
	EXPECT_EQ(
		error("# whiskermap contacts v1\n# only comments\n"),
		"line 3, column 1: no header row after the first line");
	EXPECT_EQ(
		error("# whiskermap contacts v10\n"),
		"line 1, column 1: unsupported format version 'v10' (this build reads v1)");
	EXPECT_EQ(
		error("# whiskermap contacts v1\ntime,,r\n"),
		"line 2, field 2: empty column name in the header row");
	EXPECT_EQ(
		error(HEAD + std::string(70000, '1') + "\n"),
		"line 3, column 1: line longer than 65535 characters");
}

TEST_F(ContactLogReaderTest, MissingFileAndDirectory)
{
	const auto robot = scratchbot();
	EXPECT_THROW(ContactLogReader((dir / "nowhere.csv").string(), robot, {}), core::Error);
	EXPECT_THROW(ContactLogReader(dir.string(), robot, {}), core::Error);
}
