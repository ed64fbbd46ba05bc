// Timestamped path files (ground truth, odometry, estimated paths: doc/formats.md).
#include <gtest/gtest.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/PathLog.h>

#include <filesystem>
#include <fstream>

#include "../TempDirTest.h"

using namespace whiskermap;
using PathLogTest = test::TempDirTest;

namespace
{
std::string readAll(const std::string& path)
{
	std::ifstream f(path);
	return std::string(std::istreambuf_iterator<char>(f), {});
}
}  // namespace

TEST_F(PathLogTest, WritesTheGroundTruthFormatAndReadsItBack)
{
	const auto file = path("p.txt");
	{
		world::PathLog::Writer w(file, "Odometry");
		w.write(1300000000.125, mrpt::poses::CPose2D(1.5, -2.25, 3.0));
		w.write(1300000000.25, mrpt::poses::CPose2D(1.55, -2.25, -3.0));
		EXPECT_FALSE(std::filesystem::exists(file));  // staged until close()
		w.close();
	}
	EXPECT_EQ(
		readAll(file),
		"% Odometry\n% timestamp(s)  x(m)  y(m)  yaw(rad)\n"
		"1300000000.125000 1.500000000 -2.250000000 3.000000000\n"
		"1300000000.250000 1.550000000 -2.250000000 -3.000000000\n");
	const auto p = world::PathLog::read(file);
	ASSERT_EQ(p.size(), 2u);
	EXPECT_EQ(p[1].t, 1300000000.25);
	EXPECT_EQ(p[1].pose.x, 1.55);
	EXPECT_EQ(p[1].pose.phi, -3.0);
	EXPECT_EQ(p[1].line, 4);
}

TEST_F(PathLogTest, AWriterNotClosedLeavesNothing)
{
	{
		world::PathLog::Writer w(path("p.txt"), "x");
		w.write(0, {});
	}
	EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST_F(PathLogTest, BadFilesNameTheLine)
{
	auto expectError = [&](const std::string& text, const std::string& what) {
		std::ofstream(path("bad.txt")) << text;
		try
		{
			world::PathLog::read(path("bad.txt"));
			FAIL() << "accepted: " << text;
		}
		catch (const core::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find("bad.txt: " + what), std::string::npos) << e.what();
		}
	};
	expectError("% header\n1 0 0 0\n2 0 0\n", "line 3: expected 'timestamp x y yaw', got '2 0 0'");
	expectError("1 0 0 0 5\n", "line 1: expected");
	expectError("1 0 0 0\n2 0 x 0\n", "line 2: expected");
	expectError("1 0 nan 0\n", "line 1: ");
	expectError("1 0 0 0\n\n0.5 0 0 0\n", "line 3: timestamp 0.500000 goes backwards");
	expectError("% nothing\n\n", "path file holds no poses");
	expectError(std::string("1 0 0 0\n2 0 0 0\0 junk\n", 22), "line 2: holds a control byte 0 (NUL)");
	expectError("1 0 0 0\n" + std::string(5000, '7') + "\n", "line 2: longer than 4096 bytes");
	EXPECT_THROW(world::PathLog::read(path("nowhere.txt")), core::Error);
}

TEST_F(PathLogTest, TheReaderStreamsWhatReadReturns)
{
	std::ofstream(path("p.txt")) << "% a path\r\n1 0.5 -1 0.25\r\n\n# note\n2 1.5 -2 0.5\n";
	world::PathLog::Reader r(path("p.txt"));
	world::PathLog::Entry e;
	ASSERT_TRUE(r.next(e));
	EXPECT_EQ(e.line, 2);
	EXPECT_EQ(e.pose.y, -1);
	ASSERT_TRUE(r.next(e));
	EXPECT_EQ(e.line, 5);
	EXPECT_EQ(e.pose.phi, 0.5);
	EXPECT_FALSE(r.next(e));
	EXPECT_EQ(r.count(), 2u);
	EXPECT_EQ(world::PathLog::read(path("p.txt")).size(), 2u);
}
