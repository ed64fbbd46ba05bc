#include <mrpt/maps/TMetricMapTypesRegistry.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/core/conciseMessage.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>

#include <memory>

namespace whiskermap::maps
{
mrpt::maps::TSetOfMetricMapInitializers MapConfig::load(const std::string& path)
{
	const auto file = core::openIniFile(path, "map config file");
	const std::string section = "MetricMap";
	if (!file->sectionExists(section)) throw core::Error(path + ": [" + section + "]: missing section");

	const auto& registry = mrpt::maps::internal::TMetricMapTypesRegistry::Instance().getAllRegistered();
	std::vector<std::string> keys;
	file->getAllKeys(section, keys);
	size_t ours = 0;
	std::string ourName = "hierarchicalObjectMap";
	for (const auto& k : keys)
	{
		const std::string suffix = "_count";
		const bool isCount = k.size() > suffix.size() && k.compare(k.size() - suffix.size(), suffix.size(), suffix) == 0;
		const std::string name = isCount ? k.substr(0, k.size() - suffix.size()) : k;
		if (!isCount || !registry.count(name))
			throw core::Error(
				path + ": [" + section + "] " + k + ": unknown map type '" + name +
				"' (is its library loaded?)");
		if (name == "hierarchicalObjectMap" || name == "whiskermap::maps::CHierarchicalObjectMap")
		{
			ours += file->read_uint64_t(section, k, 0);
			ourName = name;
		}
	}
	if (ours != 1)
		throw core::Error(
			path + ": [" + section + "]: needs exactly one hierarchicalObjectMap, found " +
			std::to_string(ours));

	// Our sections are checked first, outside MRPT's loader: it rewraps exceptions and
	// garbles messages that contain "] ".
	std::unique_ptr<mrpt::maps::TMetricMapInitializer>(CHierarchicalObjectMap::MapDefinition())
		->loadFromConfigFile(*file, section + "_" + ourName + "_00");
	mrpt::maps::TSetOfMetricMapInitializers inits;
	try
	{
		inits.loadFromConfigFile(*file, section);
	}
	catch (const std::exception& e)
	{
		throw core::Error(path + ": " + core::conciseMessage(e));
	}
	return inits;
}
}  // namespace whiskermap::maps
