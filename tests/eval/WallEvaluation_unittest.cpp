// Issue 11: wall length recall and precision, with hand-computed values; map_walls.csv.
#include "Fixtures.h"

#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TableCsv.h>
#include <whiskermap/eval/TouchedWalls.h>
#include <whiskermap/eval/WallEvaluation.h>

#include <cmath>
#include <fstream>

using namespace whiskermap;
using eval::WallEvaluation;

namespace
{
world::Wall wall(double x0, double y0, double x1, double y1)
{
	world::Wall w;
	w.x0 = x0, w.y0 = y0, w.x1 = x1, w.y1 = y1, w.thickness = 0.1;
	return w;
}
}  // namespace

TEST(WallEvaluation, CoveredLengthOfAParallelOffsetWall)
{
	// A: (0,0)-(4,0). B: (1,0.1)-(3,0.1), gate 0.15: A is covered on [1, 3] and, past B's
	// ends, where (x - 1)^2 + 0.1^2 <= 0.15^2: |x - 1| <= sqrt(0.0125) = 0.111803 (same at 3).
	const double cap = std::sqrt(0.15 * 0.15 - 0.01);
	EXPECT_NEAR(WallEvaluation::coveredLength(wall(0, 0, 4, 0), {wall(1, 0.1, 3, 0.1)}, 0.15, 20), 2 + 2 * cap, 1e-12);
	// Reversed direction is the same wall; overlapping coverers count once.
	EXPECT_NEAR(
		WallEvaluation::coveredLength(wall(4, 0, 0, 0), {wall(3, 0.1, 1, 0.1), wall(1.5, -0.05, 2.5, -0.05)}, 0.15, 20),
		2 + 2 * cap, 1e-12);
	// Beyond the gate, or crossing at right angles: nothing.
	EXPECT_EQ(WallEvaluation::coveredLength(wall(0, 0, 4, 0), {wall(1, 0.2, 3, 0.2)}, 0.15, 20), 0.0);
	EXPECT_EQ(WallEvaluation::coveredLength(wall(0, 0, 4, 0), {wall(2, -0.5, 2, 0.5)}, 0.15, 20), 0.0);
	// A tilted coverer (5.7 deg, within the yaw gate): (0,0)-(4,0.4). The distance from (x, 0)
	// to the line y = 0.1 x is 0.1 x / sqrt(1.01) (its foot lies on the segment for x in
	// [0, 4]), <= 0.15 for x <= 1.5 sqrt(1.01).
	EXPECT_NEAR(
		WallEvaluation::coveredLength(wall(0, 0, 4, 0), {wall(0, 0, 4, 0.4)}, 0.15, 20), 1.5 * std::sqrt(1.01), 1e-12);
}

TEST(WallEvaluation, RecallAndPrecisionByLength)
{
	// Truth A (4 m). Estimates: B (2 m, within the gate), C (2 m, 1 m away), D (1 m, crossing
	// A at right angles). Recall = (2 + 2 * 0.111803) / 4; precision = 2 / 5.
	const auto e = WallEvaluation::compute(
		{wall(0, 0, 4, 0)}, {wall(1, 0.1, 3, 0.1), wall(0, 1, 2, 1), wall(2, -0.5, 2, 0.5)}, 0.15, 20);
	EXPECT_NEAR(e.true_length_m, 4, 1e-12);
	EXPECT_NEAR(e.estimated_length_m, 5, 1e-12);
	EXPECT_NEAR(e.recall, (2 + 2 * std::sqrt(0.0125)) / 4, 1e-12);  // 0.555902
	EXPECT_NEAR(e.precision, 0.4, 1e-12);
	const auto none = WallEvaluation::compute({}, {}, 0.15, 20);
	EXPECT_EQ(none.recall, 1.0);
	EXPECT_EQ(none.precision, 1.0);
}

TEST(WallEvaluation, IntervalsUniteAndOverlap)
{
	WallEvaluation::Intervals a;
	WallEvaluation::unite(a, 2, 3);
	WallEvaluation::unite(a, 0, 1);
	WallEvaluation::unite(a, 0.5, 2.2);  // joins both
	WallEvaluation::unite(a, 4, 5);
	ASSERT_EQ(a.size(), 2u);
	EXPECT_EQ(a[0], WallEvaluation::Interval(0, 3));
	EXPECT_EQ(a[1], WallEvaluation::Interval(4, 5));
	EXPECT_DOUBLE_EQ(WallEvaluation::length(a), 4);
	EXPECT_DOUBLE_EQ(WallEvaluation::overlap(a, {{-1, 0.5}, {2.5, 4.5}}), 0.5 + 0.5 + 0.5);
	EXPECT_DOUBLE_EQ(WallEvaluation::overlap(a, {}), 0);
}

TEST(TouchedWalls, ContactsOnAWallMarkItsCentreLineNearThem)
{
	// Wall (0,0)-(4,0), 0.1 m thick; contact gate 0.1 m, spread 0.15 m.
	auto w = wall(0, 0, 4, 0);
	w.thickness = 0.1;
	eval::TouchedWalls touched({w}, 0.1, 0.15);
	touched.addContact(1, 0.05);  // on the north face: [0.85, 1.15]
	touched.addContact(1.1, -0.06);  // 1 cm past the south face: [0.95, 1.25], merged
	touched.addContact(3.95, 0);  // [3.8, 4] (clipped at the end)
	touched.addContact(4.08, 0.1);  // 8 cm past the end, 5 cm off the face: [3.93, 4]
	touched.addContact(2, 0.5);  // 45 cm off the face: not on the wall
	touched.addContact(4.3, 0);  // 30 cm past the end: not on the wall
	const auto& t = touched.intervals().at(0);
	ASSERT_EQ(t.size(), 2u);
	EXPECT_NEAR(t[0].first, 0.85, 1e-12);
	EXPECT_NEAR(t[0].second, 1.25, 1e-12);
	EXPECT_NEAR(t[1].first, 3.8, 1e-12);
	EXPECT_EQ(t[1].second, 4.0);

	// An estimated wall 5 cm off, over [0, 1]: it covers t in [0, 1 + sqrt(0.15^2 - 0.05^2)];
	// of the 0.6 m touched it covers 1.141421 - 0.85.
	const auto e = WallEvaluation::compute({w}, {wall(0, 0.05, 1, 0.05)}, 0.15, 20, &touched.intervals());
	EXPECT_TRUE(e.touched_known);
	EXPECT_NEAR(e.touched_length_m, 0.6, 1e-12);
	EXPECT_NEAR(e.touched_covered_m, 1 + std::sqrt(0.02) - 0.85, 1e-12);
	EXPECT_NEAR(e.recall_touched, (1 + std::sqrt(0.02) - 0.85) / 0.6, 1e-12);
	EXPECT_NEAR(e.recall, (1 + std::sqrt(0.02)) / 4, 1e-12);  // of the whole wall
	EXPECT_FALSE(WallEvaluation::compute({w}, {}, 0.15, 20).touched_known);
}

TEST(WallEvaluation, TrueWallsAreTheInteriorWallsThenTheArenaEdges)
{
	world::World w;
	w.x_max = 6, w.y_max = 5;
	w.walls.push_back(wall(0, 2.5, 2.2, 2.5));
	const auto t = WallEvaluation::trueWalls(w);
	ASSERT_EQ(t.size(), 5u);
	double total = 0;
	for (const auto& v : t) total += v.length();
	EXPECT_NEAR(total, 2.2 + 22, 1e-12);
	EXPECT_EQ(t[1].x1, 6.0);  // south edge
}

class WallCsvTest : public test::TempDirTest
{
   protected:
	std::string write(const std::string& text)
	{
		std::ofstream(path("walls.csv")) << text;
		return path("walls.csv");
	}
};

TEST_F(WallCsvTest, ReadsMapWallsStrictly)
{
	const std::string head = std::string(eval::TableCsv::WALLS_HEADER) + "\n";
	const auto rows = eval::TableCsv::readWalls(write(head + "0,2.5,2.2,2.5,0.1,0.9\n"));
	ASSERT_EQ(rows.size(), 1u);
	EXPECT_EQ(rows[0].wall.x1, 2.2);
	EXPECT_EQ(rows[0].wall.thickness, 0.1);
	EXPECT_EQ(rows[0].existence, 0.9);
	for (const auto& [text, error] : std::vector<std::pair<std::string, std::string>>{
			 {"x0,y0,x1,y1\n", "walls.csv: line 1: bad header 'x0,y0,x1,y1'"},
			 {head + "1,1,1,1,0.1,1\n", "walls.csv: line 2: wall of zero length"},
			 {head + "1,1,2,1,0.1,2\n", "walls.csv: line 2: column 'existence': '2' is out of range"},
			 {head + "1,1,2,1,0.1\n", "walls.csv: line 2: expected 6 columns, got 5"}})
	{
		try
		{
			eval::TableCsv::readWalls(write(text));
			ADD_FAILURE() << "accepted: " << text;
		}
		catch (const core::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
		}
	}
}
