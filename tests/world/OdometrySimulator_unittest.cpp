// Odometry presets and the simulated dead reckoning (doc/sensor-model.md, "Odometry").
#include <gtest/gtest.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/OdometrySimulator.h>

#include <Eigen/Dense>
#include <cmath>
#include <fstream>

using namespace whiskermap;
using mrpt::poses::CPose2D;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
world::OdometryNoise preset(const std::string& name)
{
	return world::OdometryNoise::load(SRC + "/config/odometry/" + name + ".ini");
}

/** Sample mean and covariance of corrupted increments of `u`. */
struct Moments
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
};
Moments draw(world::OdometrySimulator& sim, const CPose2D& u, int n)
{
	std::vector<Eigen::Vector3d> v;
	Moments m;
	for (int i = 0; i < n; i++)
	{
		const auto c = sim.corrupt(u);
		v.emplace_back(c.x(), c.y(), c.phi());
		m.mean += v.back() / n;
	}
	for (const auto& x : v) m.cov += (x - m.mean) * (x - m.mean).transpose() / (n - 1);
	return m;
}
}  // namespace

TEST(OdometryNoise, ShippedPresets)
{
	const auto exact = preset("exact");
	EXPECT_TRUE(exact.exact());
	EXPECT_FALSE(exact.matched_model);
	const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mrptDefault;
	const auto m = exact.motionModel(CPose2D(0.05, 0, 0.1));
	EXPECT_EQ(m.gaussianModel.a1, mrptDefault.gaussianModel.a1);  // bit for bit: today's actions
	EXPECT_EQ(m.gaussianModel.a2, mrptDefault.gaussianModel.a2);
	EXPECT_EQ(m.gaussianModel.minStdXY, mrptDefault.gaussianModel.minStdXY);
	const auto d = preset("default"), p = preset("poor");
	EXPECT_TRUE(d.matched_model && p.matched_model);
	EXPECT_DOUBLE_EQ(d.translation_noise, 0.05);
	EXPECT_DOUBLE_EQ(core::rad2deg(d.rotation_noise), 2);
	EXPECT_DOUBLE_EQ(d.scale_bias, 0.01);
	EXPECT_DOUBLE_EQ(p.translation_noise, 2 * d.translation_noise);
	EXPECT_DOUBLE_EQ(p.rotation_noise, 2 * d.rotation_noise);
	EXPECT_DOUBLE_EQ(p.turn_noise, 2 * d.turn_noise);
	EXPECT_DOUBLE_EQ(p.scale_bias, 2 * d.scale_bias);
}

TEST(OdometryNoise, TheMatchedModelHasTheStepsStdDevs)
{
	// MRPT: std_xy = minStdXY + a1 d + a2 |dphi|, std_phi = minStdPHI + a3 d + a4 |dphi|.
	const auto n = preset("default");
	for (const CPose2D& u : {CPose2D(0.05, 0, 0), CPose2D(0.04, -0.01, 0.2), CPose2D(0, 0, -1.5), CPose2D(2.0, 1.0, 3)})
	{
		const auto g = n.motionModel(u).gaussianModel;
		const double d = u.norm(), turn = std::abs(u.phi());
		EXPECT_NEAR(g.minStdXY + g.a1 * d + g.a2 * turn, n.min_std_xy + n.sigmaXY(d, turn) + n.scale_bias * d, 1e-15);
		EXPECT_NEAR(g.minStdPHI + g.a3 * d + g.a4 * turn, n.min_std_phi + n.sigmaPhi(d, turn), 1e-15);
	}
	// By hand for a 5 cm step: 0.05 sqrt(0.05) = 0.01118 m, 2 deg sqrt(0.05) = 0.447 deg.
	EXPECT_NEAR(n.sigmaXY(0.05, 0), 0.011180, 1e-6);
	EXPECT_NEAR(core::rad2deg(n.sigmaPhi(0.05, 0)), 0.44721, 1e-5);
}

TEST(OdometryNoise, BadFilesAreOneLineErrors)
{
	const std::string file = ::testing::TempDir() + "odometry_bad.ini";
	auto expectError = [&](const std::string& text, const std::string& what) {
		std::ofstream(file) << text;
		try
		{
			world::OdometryNoise::load(file);
			FAIL() << "accepted: " << text;
		}
		catch (const core::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
		}
	};
	const std::string ok =
		"[odometry]\ntranslation_noise=0.05\nrotation_noise_deg=2\nturn_noise=0\nturn_translation_noise=0\n";
	expectError(ok + "scale_bias=0.9\n", "[odometry] scale_bias");
	expectError(ok + "scale_bias=0\nslip=1\n", "slip: unknown key");
	expectError(ok, "scale_bias");
	expectError(ok + "scale_bias=0\n[motion_model]\nmin_std_xy=0.1\n", "[motion_model] min_std_phi_deg");
	expectError(ok + "scale_bias=0\n[wheels]\n", "wheels");
	EXPECT_THROW(world::OdometryNoise::load("bumpy"), core::Error);  // no such preset
}

TEST(OdometrySimulator, ExactOdometryIsTheTruthBitForBit)
{
	world::OdometrySimulator sim(preset("exact"), 7);
	for (int i = 0; i < 100; i++)
	{
		const CPose2D p(0.1 * i + 1e-3 / 3, std::sin(i) / 7, std::cos(i));
		const auto o = sim.next(p);
		EXPECT_EQ(o.x(), p.x());
		EXPECT_EQ(o.y(), p.y());
		EXPECT_EQ(o.phi(), p.phi());
	}
}

TEST(OdometrySimulator, SeededAndStartsAtTheTruth)
{
	auto run = [](uint64_t seed) {
		world::OdometrySimulator sim(preset("default"), seed);
		std::vector<CPose2D> out;
		for (int i = 0; i < 50; i++) out.push_back(sim.next(CPose2D(1 + 0.05 * i, 2, 0.3)));
		return out;
	};
	const auto a = run(3), b = run(3), c = run(4);
	EXPECT_EQ(a.front(), CPose2D(1, 2, 0.3));  // known start
	for (size_t i = 0; i < a.size(); i++) EXPECT_EQ(a[i], b[i]);
	EXPECT_GT((a.back() - c.back()).norm(), 1e-4);
}

TEST(OdometrySimulator, LongRunStatisticsMatchTheDefaultPreset)
{
	// 20,000 steps of 5 cm straight ahead: per step, forward = (1 + bias) d + N(0, sigma_xy^2),
	// heading error N(0, sigma_phi^2), sigma = k sqrt(d); then 20,000 in-place turns of 11.25 deg.
	const auto n = preset("default");
	world::OdometrySimulator sim(n, 11);
	const double d = 0.05, turn = core::deg2rad(11.25);
	const int N = 20000;
	const auto fwd = draw(sim, CPose2D(d, 0, 0), N);
	const double dBiased = d * (1 + n.scale_bias);
	EXPECT_NEAR(fwd.mean.x() / d - 1, n.scale_bias, 0.005);  // SE 0.0016: no bias would be 6 SE off
	EXPECT_NEAR(std::sqrt(fwd.cov(0, 0)), n.translation_noise * std::sqrt(dBiased), 0.02 * n.translation_noise * std::sqrt(d));
	EXPECT_NEAR(std::sqrt(fwd.cov(2, 2)), n.rotation_noise * std::sqrt(dBiased), 0.02 * n.rotation_noise * std::sqrt(d));
	EXPECT_NEAR(fwd.mean.z(), 0, 4 * n.rotation_noise * std::sqrt(d / N));
	const auto spin = draw(sim, CPose2D(0, 0, turn), N);
	EXPECT_NEAR(spin.mean.z(), turn, 4 * n.turn_noise * std::sqrt(turn / N));
	EXPECT_NEAR(std::sqrt(spin.cov(2, 2)), n.turn_noise * std::sqrt(turn), 0.02 * n.turn_noise * std::sqrt(turn));
	EXPECT_NEAR(std::sqrt(spin.cov(0, 0)), 0, 1e-12);  // no translation noise when turning in place
}

TEST(OdometrySimulator, DriftDoesNotDependOnTheWhiskRate)
{
	// 10 m straight, in 5 cm steps or in 50 cm steps: the same heading spread at the end
	// (2 deg sqrt(10) = 6.3 deg) and the same along-track spread (5 cm sqrt(10) = 16 cm).
	auto spread = [](double step) {
		auto n = preset("default");
		n.scale_bias = 0;
		double sumPhi = 0, sumX = 0;
		const int runs = 2000, steps = int(std::lround(10 / step));
		for (int r = 0; r < runs; r++)
		{
			world::OdometrySimulator sim(n, 100 + r);
			CPose2D o;
			for (int i = 0; i <= steps; i++) o = sim.next(CPose2D(step * i, 0, 0));
			const double along = o.x() * std::cos(o.phi()) + o.y() * std::sin(o.phi());  // distance along the drifted heading
			sumPhi += o.phi() * o.phi();
			sumX += (along - 10) * (along - 10);
		}
		return std::make_pair(std::sqrt(sumPhi / runs), std::sqrt(sumX / runs));
	};
	const auto fine = spread(0.05), coarse = spread(0.5);
	EXPECT_NEAR(core::rad2deg(fine.first), 2 * std::sqrt(10.0), 0.05 * 2 * std::sqrt(10.0));
	EXPECT_NEAR(core::rad2deg(coarse.first), 2 * std::sqrt(10.0), 0.05 * 2 * std::sqrt(10.0));
	EXPECT_NEAR(fine.second, coarse.second, 0.1 * coarse.second);
}

TEST(OdometrySimulator, ErrorsFollowMrptsOwnGaussianModel)
{
	// The spread of the drawn increments is the covariance MRPT's CActionRobotMovement2D
	// computes from the matched model (floors and bias off), cross terms included.
	auto n = preset("poor");
	n.scale_bias = 0;
	n.turn_translation_noise = 0.01;
	n.min_std_xy = n.min_std_phi = 0;
	world::OdometrySimulator sim(n, 5);
	const CPose2D u(0.2, 0.03, 0.3);
	const auto m = draw(sim, u, 40000);
	mrpt::obs::CActionRobotMovement2D action;
	action.computeFromOdometry(u, n.motionModel(u));
	const auto mrptCov = action.poseChange->getCovariance();
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			EXPECT_NEAR(m.cov(i, j), mrptCov(i, j), 0.03 * std::sqrt(mrptCov(i, i) * mrptCov(j, j))) << i << "," << j;
	EXPECT_GT(std::abs(mrptCov(1, 2)), 0.15 * std::sqrt(mrptCov(1, 1) * mrptCov(2, 2)));  // a real cross term
	EXPECT_NEAR(m.mean.x(), u.x(), 4 * std::sqrt(mrptCov(0, 0) / 40000));
}

TEST(OdometrySimulator, DeadReckoningDriftsWithTheBias)
{
	// 2,000 steps of 5 cm (100 m) straight: the odometry runs 1% long, plus noise.
	auto n = preset("default");
	n.rotation_noise = n.turn_noise = 0;
	world::OdometrySimulator sim(n, 2);
	CPose2D o;
	for (int i = 0; i <= 2000; i++) o = sim.next(CPose2D(0.05 * i, 0, 0));
	EXPECT_NEAR(o.x(), 101.0, 5 * 0.05 * std::sqrt(100.0));
	EXPECT_NEAR(o.phi(), 0, 1e-12);
}
