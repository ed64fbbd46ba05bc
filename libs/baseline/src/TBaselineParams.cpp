#include <whiskermap/baseline/TBaselineParams.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/model/ModelParams.h>

namespace whiskermap::baseline
{
TBaselineParams TBaselineParams::fromConfig(const std::string& path)
{
	const auto file = core::openIniFile(path, "config file");
	if (!file->sectionExists("MetricMap"))
		throw core::Error(path + ": not a whisker-map configuration (no [MetricMap] section)");
	TBaselineParams p;
	const std::string section = "MetricMap_hierarchicalObjectMap_00_model";
	if (!file->sectionExists(section)) return p;
	core::IniSection sec(*file, section, path);
	const auto m = model::ModelParams::fromIni(sec);
	p.table_length = m.table_length, p.table_width = m.table_width;
	p.leg_width = m.leg_width, p.texture = m.texture;
	return p;
}
}  // namespace whiskermap::baseline
