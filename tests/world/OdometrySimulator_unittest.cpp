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

TEST(OdometryNoise, ShippedPresetsFollowTheDocumentedMapping)
{
	const auto exact = preset("exact");
	EXPECT_TRUE(exact.exact());
	const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions mrptDefault;
	EXPECT_EQ(exact.motionModel.gaussianModel.a1, mrptDefault.gaussianModel.a1);  // bit for bit
	EXPECT_EQ(exact.motionModel.gaussianModel.a2, mrptDefault.gaussianModel.a2);
	EXPECT_EQ(exact.motionModel.gaussianModel.minStdXY, mrptDefault.gaussianModel.minStdXY);
	for (const char* name : {"default", "poor"})
	{
		const auto n = preset(name);
		const auto& g = n.motionModel.gaussianModel;
		EXPECT_FALSE(n.exact());
		EXPECT_EQ(n.motionModel.modelSelection, mrpt::obs::CActionRobotMovement2D::mmGaussian);
		EXPECT_NEAR(g.a1, n.translation_noise + std::abs(n.scale_bias), 1e-12) << name;
		EXPECT_EQ(g.a2, n.translation_noise_per_turn) << name;
		EXPECT_NEAR(g.a3, n.rotation_noise, 1e-15) << name;
		EXPECT_EQ(g.a4, n.rotation_noise_per_turn) << name;
		EXPECT_GT(g.minStdXY, 0) << name;
		EXPECT_GT(g.minStdPHI, 0) << name;
	}
	const auto d = preset("default"), p = preset("poor");
	EXPECT_DOUBLE_EQ(d.translation_noise, 0.05);
	EXPECT_DOUBLE_EQ(core::rad2deg(d.rotation_noise), 2);
	EXPECT_DOUBLE_EQ(d.scale_bias, 0.01);
	EXPECT_DOUBLE_EQ(p.translation_noise, 2 * d.translation_noise);
	EXPECT_DOUBLE_EQ(p.rotation_noise, 2 * d.rotation_noise);
	EXPECT_DOUBLE_EQ(p.scale_bias, 2 * d.scale_bias);
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
		"[odometry]\ntranslation_noise=0.05\ntranslation_noise_per_turn=0\nrotation_noise_deg_per_m=2\n"
		"rotation_noise_per_turn=0\n";
	expectError(ok + "scale_bias=0.9\n", "[odometry] scale_bias");
	expectError(ok + "scale_bias=0\nslip=1\n", "slip: unknown key");
	expectError(ok, "scale_bias");
	expectError(ok + "scale_bias=0\n[motion_model]\na1=0.1\n", "[motion_model] a2");
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
	// 20,000 steps of 5 cm straight ahead: per step, forward = (1 + bias) d + N(0, (a1 d)^2),
	// heading error N(0, (a3 d)^2); then 20,000 in-place turns of 11.25 deg: N(0, (a4 dphi)^2).
	const auto n = preset("default");
	world::OdometrySimulator sim(n, 11);
	const double d = 0.05, turn = core::deg2rad(11.25);
	const int N = 20000;
	const auto fwd = draw(sim, CPose2D(d, 0, 0), N);
	EXPECT_NEAR(fwd.mean.x() / d - 1, n.scale_bias, 0.0015);  // bias: SE 0.00035
	EXPECT_NEAR(std::sqrt(fwd.cov(0, 0)) / d, n.translation_noise, 0.0015);  // SE 0.00025
	EXPECT_NEAR(std::sqrt(fwd.cov(2, 2)) / d, n.rotation_noise, 0.03 * n.rotation_noise);
	EXPECT_NEAR(fwd.mean.z(), 0, 4 * n.rotation_noise * d / std::sqrt(N));
	const auto spin = draw(sim, CPose2D(0, 0, turn), N);
	EXPECT_NEAR(spin.mean.z(), turn, 4 * n.rotation_noise_per_turn * turn / std::sqrt(N));
	EXPECT_NEAR(std::sqrt(spin.cov(2, 2)) / turn, n.rotation_noise_per_turn, 0.03 * n.rotation_noise_per_turn);
	EXPECT_NEAR(std::sqrt(spin.cov(0, 0)), 0, 1e-12);  // no translation noise when turning in place (a2 = 0)
}

TEST(OdometrySimulator, ErrorsFollowMrptsOwnGaussianModel)
{
	// The spread of the drawn increments is the covariance MRPT's CActionRobotMovement2D
	// computes for the same coefficients (bias off), cross terms included.
	auto n = preset("poor");
	n.scale_bias = 0;
	n.translation_noise_per_turn = 0.01;
	world::OdometrySimulator sim(n, 5);
	const CPose2D u(0.2, 0.03, 0.3);
	const auto m = draw(sim, u, 40000);
	mrpt::obs::CActionRobotMovement2D action;
	action.computeFromOdometry(u, n.noiseModel());
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
	n.rotation_noise = n.rotation_noise_per_turn = 0;
	world::OdometrySimulator sim(n, 2);
	CPose2D o;
	for (int i = 0; i <= 2000; i++) o = sim.next(CPose2D(0.05 * i, 0, 0));
	EXPECT_NEAR(o.x(), 101.0, 5 * 0.05 * 0.05 * std::sqrt(2000.0));
	EXPECT_NEAR(o.phi(), 0, 1e-12);
}
