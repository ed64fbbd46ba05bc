#include <whiskermap/core/Angles.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/world/NoisePreset.h>

namespace whiskermap::world
{
obs::TSensorNoise NoisePreset::load(const std::string& nameOrPath)
{
	const std::string path = core::ConfigPaths::resolve(nameOrPath, "noise");
	const auto file = core::openIniFile(path, "noise file");
	const auto& cfg = *file;
	core::rejectUnknownSections(cfg, {"noise"}, "", path);
	core::IniSection sec(cfg, "noise", path);
	obs::TSensorNoise n;
	n.sigma_r = sec.number("sigma_r", 0, 1);
	n.sigma_phi = core::deg2rad(sec.number("sigma_phi_deg", 0, 180));
	n.sigma_tau = sec.number("sigma_tau", 0, 1);
	sec.finish();
	return n;
}
}  // namespace whiskermap::world
