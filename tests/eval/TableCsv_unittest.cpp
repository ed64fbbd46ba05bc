#include "Fixtures.h"

#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TableCsv.h>

#include <fstream>

using namespace whiskermap;
using eval::TableCsv;

namespace
{
class TableCsvTest : public test::TempDirTest
{
   protected:
	std::string write(const std::string& name, const std::string& text)
	{
		std::ofstream(path(name)) << text;
		return path(name);
	}
	/** The core::Error message `f` throws (empty if none). */
	template <class F>
	static std::string errorOf(F f)
	{
		try
		{
			f();
		}
		catch (const core::Error& e)
		{
			return e.what();
		}
		return "";
	}
	/** The error of reading `text` as a map CSV. */
	std::string mapError(const std::string& text)
	{
		return errorOf([&] { TableCsv::readMap(write("map.csv", text)); });
	}
	std::string map() const { return path("map.csv"); }
};

const std::string MAP_HEAD = std::string(TableCsv::MAP_HEADER) + "\n";
const std::string POSE_HEAD = std::string(TableCsv::PER_POSE_HEADER) + "\n";
}  // namespace

TEST_F(TableCsvTest, ReadsAMap)
{
	const auto rows = TableCsv::readMap(write(
		"map.csv", MAP_HEAD + "0,1.5,2,90,1,0.6,0.05,0.7,0.8,12,3\r\n7,-1,0.25,-30,1.2,0.5,0.04,0.3,1,1,1\n"));
	ASSERT_EQ(rows.size(), 2u);
	EXPECT_EQ(rows[0].id, 0);
	EXPECT_EQ(rows[0].table.x, 1.5);
	EXPECT_EQ(rows[0].table.y, 2.0);
	EXPECT_NEAR(rows[0].table.yaw, M_PI_2, 1e-15);
	EXPECT_EQ(rows[0].table.length, 1.0);
	EXPECT_EQ(rows[0].table.width, 0.6);
	EXPECT_EQ(rows[0].table.leg_width, 0.05);
	EXPECT_EQ(rows[0].table.texture, 0.7);
	EXPECT_EQ(rows[0].existence, 0.8);
	EXPECT_EQ(rows[0].contacts, 12u);
	EXPECT_EQ(rows[0].legs, 3u);
	EXPECT_EQ(rows[1].id, 7);
	ASSERT_EQ(TableCsv::tables(rows).size(), 2u);
	EXPECT_EQ(TableCsv::tables(rows)[1].x, -1.0);
	EXPECT_TRUE(TableCsv::readMap(write("header_only.csv", MAP_HEAD)).empty());
}

TEST_F(TableCsvTest, ReadsPerPoseTablesGroupedByPose)
{
	const auto perPose = TableCsv::readPerPose(
		write("pp.csv", POSE_HEAD + "0,1,1,0,1,0.6,0.05,0.7,-10.5\n2,1,1,0,1,0.6,0.05,0.7,-3\n"
								  "2,3,1,45,1,0.6,0.05,0.7,-3\n"),
		4);
	ASSERT_EQ(perPose.size(), 4u);
	EXPECT_EQ(perPose[0].size(), 1u);
	EXPECT_EQ(perPose[1].size(), 0u);
	ASSERT_EQ(perPose[2].size(), 2u);
	EXPECT_EQ(perPose[2][1].x, 3.0);
	EXPECT_EQ(perPose[3].size(), 0u);
}

TEST_F(TableCsvTest, ErrorsNameFileAndLine)
{
	const std::string good = "0,1,1,0,1,0.6,0.05,0.7,0.5,3,1\n";
	const std::string m = map();
	EXPECT_EQ(
		mapError("id,x,y,yaw,length,width,leg_width,texture,existence,contacts,legs\n" + good),
		m + ": line 1: bad header 'id,x,y,yaw,length,width,leg_width,texture,existence,contacts,legs' "
			"(expected '" + TableCsv::MAP_HEADER + "')");
	EXPECT_EQ(mapError(""), m + ": empty file (expected the header '" + TableCsv::MAP_HEADER + "')");
	// Data lines after the header -> the error after "<file>: ".
	const std::vector<std::pair<std::string, std::string>> cases{
		{good + "1,abc,1,0,1,0.6,0.05,0.7,0.5,3,1\n", "line 3: column 'x': 'abc' is not a number"},
		{"1,1,nan,0,1,0.6,0.05,0.7,0.5,3,1\n", "line 2: column 'y': 'nan' is not finite"},
		{"1,1,1,inf,1,0.6,0.05,0.7,0.5,3,1\n", "line 2: column 'yaw_deg': 'inf' is not finite"},
		{"1,1,1,0,1,0.6,0.05,0.7,0.5\n", "line 2: expected 11 columns, got 9"},
		{good + "1,1,1,0,1,0.6,0.05,0.7,0.5,3,1,\n", "line 3: expected 11 columns, got 12"},
		{good + "\n", "line 3: expected 11 columns, got 0"},
		{"1,1,1,0,1,0.6,0.05,0.7,0.5,,1\n", "line 2: column 'contacts': '' is not a number"},
		{"1,1,1,0,1,0.6,0.05,0.7,0.5, 3,1\n", "line 2: column 'contacts': ' 3' is not a number"},
		{"1,1,1,0,1,0.6,0.05,0.7,0.5,2.5,1\n", "line 2: column 'contacts': '2.5' is not a whole number"},
		{"1,1,1,0,1,0.6,0.05,0.7,0.5,3,5\n", "line 2: column 'legs': '5' is out of range [0, 4]"},
		{"1,1,1,0,1,0.6,0.05,0.7,1.5,2,1\n", "line 2: column 'existence': '1.5' is out of range [0, 1]"},
		{"1,1,1,0,0,0.6,0.05,0.7,1,2,1\n", "line 2: column 'length': '0' is out of range [1e-06, 10000]"},
		{good + good, "line 3: duplicate id 0"},
	};
	for (const auto& [rows, error] : cases) EXPECT_EQ(mapError(MAP_HEAD + rows), m + ": " + error);

	const auto missing = path("nowhere.csv");
	EXPECT_EQ(errorOf([&] { TableCsv::readMap(missing); }), missing + ": no such file");
}

TEST_F(TableCsvTest, PerPoseErrors)
{
	const auto pp = write("pp.csv", POSE_HEAD + "0,1,1,0,1,0.6,0.05,0.7,-1\n3,1,1,0,1,0.6,0.05,0.7,-1\n");
	EXPECT_EQ(errorOf([&] { TableCsv::readPerPose(pp, 3); }),
		pp + ": line 3: pose 3 out of range (3 poses)");
	const auto nan = write("nan.csv", POSE_HEAD + "0,1,1,0,1,0.6,0.05,0.7,NaN\n");
	EXPECT_EQ(errorOf([&] { TableCsv::readPerPose(nan, 3); }),
		nan + ": line 2: column 'log_posterior': 'NaN' is not finite");
	// A map CSV is not a per-pose CSV.
	EXPECT_THROW(TableCsv::readPerPose(write("map.csv", MAP_HEAD), 3), core::Error);
}

// Regression (issue 8): per-pose tables were read whole into one vector per pose (memory
// grew with --poses, up to 1e9 vectors) and lines were unbounded.
TEST_F(TableCsvTest, PerPoseRowsStreamInPoseOrderWithBoundedLines)
{
	const auto pp = write("order.csv", POSE_HEAD + "2,1,1,0,1,0.6,0.05,0.7,-1\n1,1,1,0,1,0.6,0.05,0.7,-1\n");
	EXPECT_EQ(errorOf([&] { TableCsv::readPerPose(pp, 3); }),
			  pp + ": line 3: pose 1 after pose 2 (rows must be in pose order, as whisker-map writes them)");
	const auto big = write("big.csv", POSE_HEAD + "0,1,1,0,1,0.6,0.05,0.7,-1\n");
	TableCsv::PerPoseReader r(big, 1000000000);  // no allocation per pose
	std::vector<whiskermap::world::Table> tables;
	ASSERT_TRUE(r.next(tables));
	EXPECT_EQ(tables.size(), 1u);
	ASSERT_TRUE(r.next(tables));
	EXPECT_TRUE(tables.empty());
	const auto longLine = write("long.csv", MAP_HEAD + std::string(100000, '1') + "\n");
	EXPECT_EQ(errorOf([&] { TableCsv::readMap(longLine); }), longLine + ": line 2: longer than 4096 bytes");
	const auto nul = write("nul.csv", MAP_HEAD + std::string("0,1,1,0,1,0.6,0.05,0.7,0.5,3\0\n", 30));
	EXPECT_EQ(errorOf([&] { TableCsv::readMap(nul); }), nul + ": line 2: holds a control byte 0 (NUL)");
}

// The lasting map's spread columns (sd_x, sd_y, sd_yaw_deg after legs), with or without the
// class column last; a file without them has no spreads; a negative or absurd sd is refused.
TEST_F(TableCsvTest, ReadsTheOptionalSpreadColumns)
{
	const std::string row = "0,1.5,2,90,1,0.6,0.05,0.7,0.8,12,3";
	bool hasClass = true;
	auto rows = TableCsv::readMap(
		write("map.csv", std::string(TableCsv::MAP_HEADER_SPREAD) + "\n" + row + ",0.002,0.0015,0.25\n"), &hasClass);
	ASSERT_EQ(rows.size(), 1u);
	EXPECT_FALSE(hasClass);
	ASSERT_TRUE(rows[0].spread.has_value());
	EXPECT_EQ(rows[0].spread->x, 0.002);
	EXPECT_EQ(rows[0].spread->y, 0.0015);
	EXPECT_EQ(rows[0].spread->yaw_deg, 0.25);
	EXPECT_EQ(rows[0].legs, 3u);
	rows = TableCsv::readMap(
		write("map.csv", std::string(TableCsv::MAP_HEADER_SPREAD_CLASS) + "\n" + row + ",0.002,0.0015,0.25,chair\n"),
		&hasClass);
	EXPECT_TRUE(hasClass);
	EXPECT_EQ(rows[0].table.object_class.str(), "chair");
	EXPECT_EQ(rows[0].spread->yaw_deg, 0.25);
	EXPECT_FALSE(TableCsv::readMap(write("map.csv", MAP_HEAD + row + "\n"))[0].spread.has_value());
	EXPECT_EQ(
		mapError(std::string(TableCsv::MAP_HEADER_SPREAD) + "\n" + row + ",-0.002,0.0015,0.25\n"),
		map() + ": line 2: column 'sd_x': '-0.002' is out of range [0, 10000]");
	EXPECT_EQ(
		mapError(std::string(TableCsv::MAP_HEADER_SPREAD) + "\n" + row + ",0.002,0.0015\n"),
		map() + ": line 2: expected 14 columns, got 13");
}
