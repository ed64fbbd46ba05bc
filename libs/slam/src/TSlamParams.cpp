#include <whiskermap/core/Angles.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/slam/TSlamParams.h>

#include <filesystem>
#include <map>

namespace whiskermap::slam
{
namespace
{
namespace fs = std::filesystem;

/** `value` next to the .ini if such a file exists there, else `value` as given. */
std::string besideIni(const std::string& ini, const std::string& value)
{
	if (value.empty() || fs::path(value).is_absolute()) return value;
	const fs::path near = fs::path(ini).parent_path() / value;
	return fs::exists(near) ? near.string() : value;
}
}  // namespace

mrpt::obs::CActionRobotMovement2D::TMotionModelOptions TSlamParams::motionModel(const mrpt::poses::CPose2D& increment) const
{
	auto model = motion.motionModel(increment);
	auto& g = model.gaussianModel;
	g.a1 *= motion_noise_scale, g.a2 *= motion_noise_scale;
	g.a3 *= motion_noise_scale, g.a4 *= motion_noise_scale;
	return model;
}

TSlamParams TSlamParams::load(const std::string& path)
{
	using PF = mrpt::bayes::CParticleFilter;
	const auto file = core::openIniFile(path, "slam config file");
	core::rejectUnknownSections(*file, {"slam", "smooth"}, "", path);  // [smooth]: smooth::TSmoothParams
	core::IniSection sec(*file, "slam", path);
	TSlamParams p;
	p.particles = static_cast<unsigned>(sec.integer("particles", p.particles, 1, 100000));
	p.seed = static_cast<uint64_t>(sec.integer("seed", static_cast<long>(p.seed), 0, 1L << 53));
	const std::string mapConfig = besideIni(path, sec.text("map_config", "whisker-map.ini"));
	p.map_config = fs::exists(mapConfig) ? mapConfig : core::ConfigPaths::find(mapConfig);
	p.motion = world::OdometryNoise::load(besideIni(path, sec.text("odometry_model", "default")));
	// Exact odometry without a [motion_model]: its matched model has zero noise, so the
	// particles follow the odometry and SLAM maps at the recorded (true) poses.
	if (!p.motion.matched_model && p.motion.exact()) p.motion.matched_model = true;
	if (!p.motion.matched_model)
		sec.fail("odometry_model", "the odometry file has no [motion_model] section and is not exact");
	p.motion_noise_scale = sec.number("motion_noise_scale", p.motion_noise_scale, 0.01, 100);
	p.proposal_samples = static_cast<unsigned>(sec.integer("proposal_samples", p.proposal_samples, 1, 10000));
	p.batch_sweeps = static_cast<unsigned>(sec.integer("batch_sweeps", p.batch_sweeps, 0, 1000));
	p.manhattan_walls = sec.boolean("manhattan_walls", p.manhattan_walls);
	p.wall_axis = core::deg2rad(sec.number("wall_axis_deg", core::rad2deg(p.wall_axis), -90, 90));
	p.wall_extension = sec.number("wall_extension", p.wall_extension, 0, 100);
	p.leg_merge_gap = sec.number("leg_merge_gap", p.leg_merge_gap, 0, 1);
	p.disjoint_tables = sec.boolean("disjoint_tables", p.disjoint_tables);
	p.resample_ess = sec.number("resample_ess", p.resample_ess, 0, 1);
	const std::map<std::string, PF::TParticleResamplingAlgorithm> methods = {
		{"multinomial", PF::prMultinomial}, {"residual", PF::prResidual},
		{"stratified", PF::prStratified}, {"systematic", PF::prSystematic}};
	const std::string method = sec.text("resampling", "systematic");
	const auto it = methods.find(method);
	if (it == methods.end())
		sec.fail("resampling", "'" + method + "' is not one of multinomial, residual, stratified, systematic");
	p.resampling = it->second;
	sec.finish();
	return p;
}
}  // namespace whiskermap::slam
