#include <whiskermap/core/Angles.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/world/OdometryNoise.h>

namespace whiskermap::world
{
using Options = mrpt::obs::CActionRobotMovement2D::TMotionModelOptions;

bool OdometryNoise::exact() const
{
	return translation_noise == 0 && translation_noise_per_turn == 0 && rotation_noise == 0 &&
		   rotation_noise_per_turn == 0 && scale_bias == 0;
}

Options OdometryNoise::noiseModel() const
{
	Options o;
	o.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	o.gaussianModel = Options::TOptions_GaussianModel(
		translation_noise, translation_noise_per_turn, rotation_noise, rotation_noise_per_turn, 0, 0);
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
	n.translation_noise = sec.number("translation_noise", 0, 1);
	n.translation_noise_per_turn = sec.number("translation_noise_per_turn", 0, 1);
	n.rotation_noise = core::deg2rad(sec.number("rotation_noise_deg_per_m", 0, 90));
	n.rotation_noise_per_turn = sec.number("rotation_noise_per_turn", 0, 1);
	n.scale_bias = sec.number("scale_bias", -0.5, 0.5);
	sec.finish();
	if (!cfg.sectionExists("motion_model")) return n;  // MRPT's default model

	core::IniSection mm(cfg, "motion_model", path);
	auto& g = n.motionModel.gaussianModel;
	n.motionModel.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	g.a1 = mm.number("a1", 0, 1);
	g.a2 = mm.number("a2", 0, 1);
	g.a3 = core::deg2rad(mm.number("a3_deg_per_m", 0, 90));
	g.a4 = mm.number("a4", 0, 1);
	g.minStdXY = mm.number("min_std_xy", 0, 1);
	g.minStdPHI = core::deg2rad(mm.number("min_std_phi_deg", 0, 90));
	mm.finish();
	return n;
}
}  // namespace whiskermap::world
