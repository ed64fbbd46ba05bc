#include "Fixtures.h"

#include <whiskermap/core/Error.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/PerPoseEvaluation.h>

#include <cmath>

using namespace whiskermap;
using eval::MapEvaluation;
using test::table;

namespace
{
const eval::EvalOptions OPTS;  // gates 0.25 m, 20 deg; OSPA c = 0.5, p = 1
const std::vector<world::Table> TRUTH{table(1, 1, 0), table(3, 1, 45), table(2, 3, 150)};

MapEvaluation score(const std::vector<world::Table>& estimated)
{
	return MapEvaluation::compute(TRUTH, estimated, OPTS);
}
}  // namespace

TEST(MapEvaluation, PerfectMap)
{
	const auto e = score(TRUTH);
	EXPECT_EQ(e.matched, 3u);
	EXPECT_EQ(e.truthMatch, (std::vector<int>{0, 1, 2}));
	EXPECT_EQ(e.figures.precision, 1.0);
	EXPECT_EQ(e.figures.recall, 1.0);
	EXPECT_EQ(e.figures.f1, 1.0);
	EXPECT_EQ(e.figures.count_error, 0.0);
	EXPECT_NEAR(e.figures.rmse_m, 0, 1e-12);
	EXPECT_NEAR(e.figures.yaw_err_deg, 0, 1e-9);
	EXPECT_NEAR(e.figures.ospa, 0, 1e-12);
}

TEST(MapEvaluation, OneMissing)
{
	const auto e = score({TRUTH[2], TRUTH[0]});
	EXPECT_EQ(e.truthMatch, (std::vector<int>{1, -1, 0}));
	EXPECT_EQ(e.figures.precision, 1.0);
	EXPECT_NEAR(e.figures.recall, 2.0 / 3, 1e-12);
	EXPECT_NEAR(e.figures.f1, 0.8, 1e-12);
	EXPECT_EQ(e.figures.count_error, -1.0);
	EXPECT_NEAR(e.figures.ospa, 0.5 / 3, 1e-12);
}

TEST(MapEvaluation, OneExtra)
{
	auto est = TRUTH;
	est.push_back(table(3.5, 3.5, 0));
	const auto e = score(est);
	EXPECT_EQ(e.matched, 3u);
	EXPECT_NEAR(e.figures.precision, 0.75, 1e-12);
	EXPECT_EQ(e.figures.recall, 1.0);
	EXPECT_EQ(e.figures.count_error, 1.0);
	EXPECT_NEAR(e.figures.ospa, 0.5 / 4, 1e-12);
}

TEST(MapEvaluation, ShiftedPastTheGateIsMissedAndExtra)
{
	auto est = TRUTH;
	est[1].x += 0.3;  // 0.3 m > 0.25 m gate
	const auto e = score(est);
	EXPECT_EQ(e.matched, 2u);
	EXPECT_EQ(e.truthMatch[1], -1);
	EXPECT_NEAR(e.figures.precision, 2.0 / 3, 1e-12);
	EXPECT_NEAR(e.figures.recall, 2.0 / 3, 1e-12);
	EXPECT_EQ(e.figures.count_error, 0.0);
	EXPECT_NEAR(e.figures.ospa, 0.3 / 3, 1e-12);  // OSPA has no gate, only its cut-off
}

TEST(MapEvaluation, ShiftWithinTheGateIsCentreError)
{
	auto est = TRUTH;
	est[0].x += 0.03, est[0].y += 0.04;  // 5 cm
	est[2].yaw += core::deg2rad(10);
	const auto e = score(est);
	EXPECT_EQ(e.matched, 3u);
	EXPECT_NEAR(e.figures.rmse_m, std::sqrt(0.05 * 0.05 / 3), 1e-12);
	EXPECT_NEAR(e.figures.yaw_err_deg, 10.0 / 3, 1e-9);
	EXPECT_NEAR(e.figures.ospa, 0.05 / 3, 1e-12);
}

TEST(MapEvaluation, YawIsModulo180Degrees)
{
	auto turned = TRUTH;
	for (auto& t : turned) t.yaw += M_PI;  // the same tables
	auto e = score(turned);
	EXPECT_EQ(e.matched, 3u);
	EXPECT_NEAR(e.figures.yaw_err_deg, 0, 1e-9);

	auto crossed = TRUTH;
	crossed[0].yaw += M_PI_2;  // same centre, the other way round: not the same table
	e = score(crossed);
	EXPECT_EQ(e.matched, 2u);
	EXPECT_EQ(e.truthMatch[0], -1);
	EXPECT_NEAR(e.figures.ospa, 0, 1e-12);  // OSPA only sees centres
}

TEST(MapEvaluation, OptimalNotGreedyMatching)
{
	// Greedy nearest-first would pair the estimate at 0.11 with the truth at 0.2 (0.09 m) and
	// leave the estimate at 0.42 unmatched; the optimal assignment matches both.
	const std::vector<world::Table> truth{table(0, 0, 0), table(0.2, 0, 0)};
	const auto e = MapEvaluation::compute(truth, {table(0.11, 0, 0), table(0.42, 0, 0)}, OPTS);
	EXPECT_EQ(e.truthMatch, (std::vector<int>{0, 1}));
	EXPECT_NEAR(e.figures.rmse_m, std::sqrt((0.11 * 0.11 + 0.22 * 0.22) / 2), 1e-12);
}

TEST(MapEvaluation, AlignedCentreErrorIsTheMapsShapeWithoutItsOffset)
{
	// The map moved whole (3 cm along x, 2 cm along y, turned 1 degree about the origin), and
	// one table 1 cm further: the raw centre error carries the motion, the aligned one only
	// what is left once the best rigid motion is taken out (the 1 cm, shared by the fit).
	const double yaw = M_PI / 180;
	std::vector<world::Table> moved;
	for (const auto& t : TRUTH)
		moved.push_back(table(
			std::cos(yaw) * t.x - std::sin(yaw) * t.y + 0.03, std::sin(yaw) * t.x + std::cos(yaw) * t.y + 0.02,
			t.yaw * 180 / M_PI + 1));
	auto e = score(moved);
	EXPECT_EQ(e.matched, 3u);
	EXPECT_GT(e.figures.rmse_m, 0.03);
	EXPECT_NEAR(e.figures.rmse_aligned_m, 0, 1e-9);
	moved[2].x += 0.01;
	e = score(moved);
	EXPECT_GT(e.figures.rmse_aligned_m, 0.002);
	EXPECT_LT(e.figures.rmse_aligned_m, 0.01);
	// Fewer than three matched: no shape to speak of.
	EXPECT_TRUE(std::isnan(score({moved[0], moved[1]}).figures.rmse_aligned_m));
	EXPECT_FALSE(std::isnan(score({moved[0], moved[1]}).figures.rmse_m));
}

TEST(MapEvaluation, EmptySetsAndBadOptions)
{
	const auto none = MapEvaluation::compute({}, {}, OPTS);
	EXPECT_EQ(none.figures.f1, 1.0);
	EXPECT_TRUE(std::isnan(none.figures.rmse_m));
	const auto nothingFound = score({});
	EXPECT_EQ(nothingFound.figures.precision, 1.0);
	EXPECT_EQ(nothingFound.figures.recall, 0.0);
	EXPECT_EQ(nothingFound.figures.f1, 0.0);
	EXPECT_EQ(nothingFound.figures.ospa, 0.5);
	eval::EvalOptions bad;
	bad.gate_yaw_deg = 0;
	EXPECT_THROW(MapEvaluation::compute(TRUTH, TRUTH, bad), core::Error);
}

TEST(PerPoseEvaluation, AveragesOverPosesAllAndLocal)
{
	const std::vector<world::Table> truth{table(1, 1, 0), table(4, 1, 0)};
	// Pose 0 (near A) finds A, pose 1 (near A) finds nothing, pose 2 (near B) finds A and B.
	const std::vector<std::vector<world::Table>> found{{truth[0]}, {}, truth};
	const std::vector<mrpt::poses::CPose2D> robot{{1, 0.3, 0}, {1.2, 1.8, 0}, {4, 2, 0}};
	const auto e = eval::PerPoseEvaluation::compute(truth, found, robot, OPTS);
	EXPECT_EQ(e.poses, 3u);
	EXPECT_NEAR(e.all.precision, 1.0, 1e-12);
	EXPECT_NEAR(e.all.recall, (0.5 + 0 + 1) / 3, 1e-12);
	EXPECT_NEAR(e.all.count_error, (-1 - 2 + 0) / 3.0, 1e-12);
	EXPECT_NEAR(e.all.ospa, (0.25 + 0.5 + 0) / 3, 1e-12);
	EXPECT_NEAR(e.all.rmse_m, 0, 1e-12);  // over the two poses with matches
	ASSERT_TRUE(e.local.has_value());
	// Local truth: {A}, {A}, {B}. Pose 2's A is then an extra table.
	EXPECT_NEAR(e.local->precision, (1 + 1 + 0.5) / 3, 1e-12);
	EXPECT_NEAR(e.local->recall, (1 + 0 + 1) / 3.0, 1e-12);
	EXPECT_NEAR(e.local->count_error, (0 - 1 + 1) / 3.0, 1e-12);

	const auto noPoses = eval::PerPoseEvaluation::compute(truth, found, {}, OPTS);
	EXPECT_FALSE(noPoses.local.has_value());
	EXPECT_THROW(eval::PerPoseEvaluation::compute(truth, found, {robot[0]}, OPTS), core::Error);
}
