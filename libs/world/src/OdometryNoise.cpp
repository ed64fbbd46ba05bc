#include <whiskermap/core/Angles.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/world/OdometryNoise.h>

#include <cmath>

namespace whiskermap::world
{
using Options = mrpt::obs::CActionRobotMovement2D::TMotionModelOptions;

bool OdometryNoise::exact() const
{
	return translation_noise == 0 && rotation_noise == 0 && turn_noise == 0 && turn_translation_noise == 0 &&
		   scale_bias == 0;
}

double OdometryNoise::sigmaXY(double d, double dphi) const
{
	return translation_noise * std::sqrt(d) + turn_translation_noise * std::sqrt(std::abs(dphi));
}

double OdometryNoise::sigmaPhi(double d, double dphi) const
{
	return rotation_noise * std::sqrt(d) + turn_noise * std::sqrt(std::abs(dphi));
}

Options OdometryNoise::motionModel(const mrpt::poses::CPose2D& increment) const
{
	Options o;
	if (!matched_model) return o;
	// Per unit of this step's motion: k sqrt(x) = (k / sqrt(x)) x (doc/sensor-model.md, "Odometry").
	const double d = increment.norm(), turn = std::abs(increment.phi());
	auto perUnit = [](double k, double x) { return x > 0 ? k / std::sqrt(x) : 0.0; };
	o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	o.gaussianModel = Options::TOptions_GaussianModel(
		perUnit(translation_noise, d) + std::abs(scale_bias), perUnit(turn_translation_noise, turn),
		perUnit(rotation_noise, d), perUnit(turn_noise, turn), min_std_xy, min_std_phi);
	return o;
}

OdometryNoise OdometryNoise::load(const std::string& nameOrPath)
{
	const std::string path = core::ConfigPaths::resolve(nameOrPath, "odometry");
	const auto file = core::openIniFile(path, "odometry file");
	const auto& cfg = *file;
	core::rejectUnknownSections(cfg, {"odometry", "motion_model"}, "", path);
	OdometryNoise n;
	core::IniSection sec(cfg, "odometry", path);
	n.translation_noise = sec.number("translation_noise", 0, 10);
	n.rotation_noise = core::deg2rad(sec.number("rotation_noise_deg", 0, 90));
	n.turn_noise = sec.number("turn_noise", 0, 1);
	n.turn_translation_noise = sec.number("turn_translation_noise", 0, 10);
	n.scale_bias = sec.number("scale_bias", -0.5, 0.5);
	sec.finish();
	if (!cfg.sectionExists("motion_model")) return n;
	core::IniSection mm(cfg, "motion_model", path);
	n.matched_model = true;
	n.min_std_xy = mm.number("min_std_xy", 0, 1);
	n.min_std_phi = core::deg2rad(mm.number("min_std_phi_deg", 0, 90));
	mm.finish();
	return n;
}
}  // namespace whiskermap::world
