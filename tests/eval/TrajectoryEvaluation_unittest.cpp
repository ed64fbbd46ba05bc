// Trajectory figures (doc/evaluation.md, "Trajectory figures") against hand-computed values.
#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/eval/TrajectoryEvaluation.h>

#include "../TempDirTest.h"

#include <cmath>

using namespace whiskermap;
using Entry = world::PathLog::Entry;
using mrpt::poses::CPose2D;

namespace
{
/** 81 poses along x from 0 to 10 m, 0.125 m (exact in binary) and 0.125 s apart, heading 0;
 *  as if read from lines 3, 4, ... */
std::vector<Entry> straight()
{
	std::vector<Entry> p;
	for (int i = 0; i <= 80; i++) p.push_back({1300000000.0 + i * 0.125, {0.125 * i, 0, 0}, i + 3});
	return p;
}
eval::TrajectoryEvaluation evaluate(const std::vector<Entry>& est, const std::vector<Entry>& truth)
{
	return eval::TrajectoryEvaluation::compute(est, truth, eval::EvalOptions{}, "est.txt", "gt.txt");
}
}  // namespace

TEST(TrajectoryEvaluation, ThePathItselfScoresZero)
{
	const auto r = evaluate(straight(), straight());
	EXPECT_EQ(r.poses, 81u);
	EXPECT_NEAR(r.length_m, 10, 1e-12);
	EXPECT_EQ(r.ate_rmse_m, 0);
	EXPECT_EQ(r.ate_max_m, 0);
	EXPECT_NEAR(r.aligned_rmse_m, 0, 1e-15);
	EXPECT_EQ(r.rpe_segments, 73u);  // from poses 0..72 a 1 m segment (8 steps) ends inside the path
	EXPECT_NEAR(r.rpe_trans, 0, 1e-15);
	EXPECT_EQ(r.final_error_m, 0);
}

TEST(TrajectoryEvaluation, AScaleDriftOfKnownSize)
{
	// The estimate runs 2% long: error 0.02 x at each pose.
	auto est = straight();
	for (auto& e : est) e.pose = {1.02 * e.pose.x, 0, 0};
	const auto r = evaluate(est, straight());
	// RMSE = 0.02 sqrt(mean x^2); mean over k = 0..80 of (k / 8)^2 = (80 * 161 / 6) / 64 = 33.5416...
	const double meanSq = 80.0 * 161 / 6 / 64;
	EXPECT_NEAR(r.ate_rmse_m, 0.02 * std::sqrt(meanSq), 1e-12);
	EXPECT_NEAR(r.ate_max_m, 0.2, 1e-12);
	EXPECT_NEAR(r.final_error_m, 0.2, 1e-12);
	EXPECT_NEAR(r.rpe_trans, 0.02, 1e-9);  // 2 cm per metre on every segment
	EXPECT_NEAR(r.rpe_rot_deg_per_m, 0, 1e-12);
	// The best rigid alignment cannot undo a scale: it centres the error (x around 5 m):
	// 0.02 (x - 5), RMSE 0.02 sqrt(mean x^2 - 25).
	EXPECT_NEAR(r.aligned_rmse_m, 0.02 * std::sqrt(meanSq - 25), 1e-9);
	EXPECT_NEAR(r.alignment.yaw, 0, 1e-12);
}

TEST(TrajectoryEvaluation, ARigidMotionIsUndoneByTheAlignment)
{
	// The estimate is the truth turned 20 degrees about the origin and shifted (0.3, -0.1):
	// raw errors grow along the path, aligned ones vanish, and relative motion is exact.
	auto est = straight();
	const double yaw = core::deg2rad(20);
	for (auto& e : est)
		e.pose = (CPose2D(0.3, -0.1, yaw) + CPose2D(e.pose)).asTPose();
	const auto r = evaluate(est, straight());
	EXPECT_NEAR(r.aligned_rmse_m, 0, 1e-12);
	EXPECT_NEAR(r.aligned_max_m, 0, 1e-12);
	EXPECT_NEAR(core::rad2deg(r.alignment.yaw), -20, 1e-9);
	EXPECT_NEAR(r.rpe_trans, 0, 1e-12);
	EXPECT_NEAR(r.rpe_rot_deg_per_m, 0, 1e-12);
	EXPECT_NEAR(r.ate_yaw_rmse_deg, 20, 1e-9);
	// Final pose: (10, 0) became (0.3 + 10 cos 20, -0.1 + 10 sin 20).
	EXPECT_NEAR(r.final_error_m, std::hypot(0.3 + 10 * std::cos(yaw) - 10, -0.1 + 10 * std::sin(yaw)), 1e-12);
	EXPECT_NEAR(r.final_yaw_err_deg, 20, 1e-9);
}

TEST(TrajectoryEvaluation, AHeadingDriftShowsInRpe)
{
	// The estimate turns at 1 degree per metre as it goes (an arc instead of a line): over a
	// 1 m segment the relative heading is 1 degree off.
	std::vector<Entry> est;
	CPose2D p;
	for (int i = 0; i <= 80; i++)
	{
		est.push_back({1300000000.0 + i * 0.125, p.asTPose(), 0});
		p = p + CPose2D(0.125, 0, core::deg2rad(0.125));
	}
	const auto r = evaluate(est, straight());
	EXPECT_NEAR(r.rpe_rot_deg_per_m, 1.0, 1e-9);
	EXPECT_NEAR(r.final_yaw_err_deg, 10.0, 1e-9);
}

TEST(TrajectoryEvaluation, MismatchesAreErrorsNamingTheLines)
{
	auto est = straight();
	est.pop_back();
	try
	{
		evaluate(est, straight());
		FAIL();
	}
	catch (const core::Error& e)
	{
		EXPECT_STREQ(e.what(), "est.txt: holds 80 poses, but gt.txt holds 81 (one line per sweep in both)");
	}
	est = straight();
	est[7].t += 0.01;
	try
	{
		evaluate(est, straight());
		FAIL();
	}
	catch (const core::Error& e)
	{
		EXPECT_STREQ(e.what(), "est.txt: line 10: timestamp 1300000000.885000, but 1300000000.875000 at gt.txt: line 10");
	}
}

TEST(TrajectoryEvaluation, JsonAndTextReports)
{
	auto est = straight();
	for (auto& e : est) e.pose = {1.02 * e.pose.x, 0, 0};
	eval::EvalReport report;
	report.trajectory = evaluate(est, straight());
	const auto json = report.toJson();
	EXPECT_EQ(json.substr(0, 45), "{\n  \"trajectory\": {\n    \"poses\": 81,\n    \"len");
	EXPECT_NE(json.find("\"ate_rmse_m\": 0.115830,\n    \"ate_max_m\": 0.200000,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"rpe_segments\": 73,\n    \"rpe_trans\": 0.020000,"), std::string::npos) << json;
	EXPECT_EQ(json.find("precision"), std::string::npos);  // no map, no map figures
	const auto text = report.toText();
	EXPECT_NE(text.find("trajectory: 81 poses, 10.000 m of true travel"), std::string::npos) << text;
	EXPECT_NE(text.find("ATE RMSE (m)"), std::string::npos) << text;
	EXPECT_NE(text.find("final pose error: 0.2000 m"), std::string::npos) << text;
}

class TrajectoryFiles : public test::TempDirTest
{
   protected:
	std::string write(const std::string& name, const std::vector<Entry>& path)
	{
		world::PathLog::Writer w(this->path(name), name);
		for (const auto& e : path) w.write(e.t, CPose2D(e.pose));
		w.close();
		return this->path(name);
	}
};

TEST_F(TrajectoryFiles, StreamedFromFilesTheFiguresAreThoseOfThePathsInMemory)
{
	// A wobbling, turning estimate: every figure non-trivial. Streamed from the files, the
	// figures equal those of the same files read into memory, to the last bit.
	auto est = straight();
	for (size_t i = 0; i < est.size(); i++)
		est[i].pose = {1.01 * est[i].pose.x + 0.03 * std::sin(0.3 * i), 0.02 * std::cos(0.2 * i), 0.01 * i};
	const auto e = write("est.txt", est), g = write("gt.txt", straight());
	const auto a = eval::TrajectoryEvaluation::compute(e, g, eval::EvalOptions{});
	const auto b = eval::TrajectoryEvaluation::compute(
		world::PathLog::read(e), world::PathLog::read(g), eval::EvalOptions{});
	EXPECT_GT(a.aligned_rmse_m, 0.01);
	EXPECT_GT(a.rpe_rot_deg_per_m, 0.1);
	EXPECT_EQ(a.poses, b.poses);
	EXPECT_EQ(a.rpe_segments, b.rpe_segments);
	for (const auto& [x, y] : {std::pair{a.length_m, b.length_m}, {a.ate_rmse_m, b.ate_rmse_m},
			 {a.ate_max_m, b.ate_max_m}, {a.ate_yaw_rmse_deg, b.ate_yaw_rmse_deg}, {a.alignment.yaw, b.alignment.yaw},
			 {a.alignment.t.x(), b.alignment.t.x()}, {a.aligned_rmse_m, b.aligned_rmse_m},
			 {a.aligned_max_m, b.aligned_max_m}, {a.rpe_trans, b.rpe_trans}, {a.rpe_rot_deg_per_m, b.rpe_rot_deg_per_m},
			 {a.final_error_m, b.final_error_m}, {a.final_yaw_err_deg, b.final_yaw_err_deg}})
		EXPECT_EQ(x, y);
	// A limit scores the first poses of each; both must hold that many.
	const auto first = eval::TrajectoryEvaluation::compute(e, g, eval::EvalOptions{}, 40);
	EXPECT_EQ(first.poses, 40u);
	EXPECT_NEAR(first.length_m, 39 * 0.125, 1e-12);
	try
	{
		eval::TrajectoryEvaluation::compute(e, g, eval::EvalOptions{}, 82);
		FAIL();
	}
	catch (const core::Error& x)
	{
		EXPECT_EQ(std::string(x.what()), e + ": holds 81 poses, 82 needed (one line per sweep)");
	}
	// Unequal counts are found before any figure, as in memory.
	auto shorter = straight();
	shorter.pop_back();
	try
	{
		eval::TrajectoryEvaluation::compute(write("short.txt", shorter), g, eval::EvalOptions{});
		FAIL();
	}
	catch (const core::Error& x)
	{
		EXPECT_EQ(std::string(x.what()), path("short.txt") + ": holds 80 poses, but " + g + " holds 81 (one line per sweep in both)");
	}
}
