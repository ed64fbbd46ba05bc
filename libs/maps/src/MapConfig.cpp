#include <mrpt/maps/TMetricMapTypesRegistry.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/core/conciseMessage.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace whiskermap::maps
{
mrpt::maps::TSetOfMetricMapInitializers MapConfig::load(const std::string& path)
{
	const auto file = core::openIniFile(path, "map config file");
	const std::string section = "MetricMap";
	if (!file->sectionExists(section)) throw core::Error(path + ": [" + section + "]: missing section");
	constexpr long MAX_MAPS = 100;  // per map type

	const auto& registry = mrpt::maps::internal::TMetricMapTypesRegistry::Instance().getAllRegistered();
	std::vector<std::string> keys;
	file->getAllKeys(section, keys);
	core::IniSection counts(*file, section, path);
	size_t ours = 0;
	std::string ourName = "hierarchicalObjectMap";
	std::vector<std::string> prefixes;  // sections the declared maps may read
	for (const auto& k : keys)
	{
		const std::string suffix = "_count";
		const bool isCount = k.size() > suffix.size() && k.compare(k.size() - suffix.size(), suffix.size(), suffix) == 0;
		const std::string name = isCount ? k.substr(0, k.size() - suffix.size()) : k;
		if (!isCount || !registry.count(name))
			counts.fail(k, "unknown map type '" + name + "' (is its library loaded?)");
		const long n = counts.integer(k, 0, MAX_MAPS);
		for (long i = 0; i < n; i++)
		{
			char idx[24];
			std::snprintf(idx, sizeof(idx), "%02ld", i);
			prefixes.push_back(section + "_" + name + "_" + idx + "_");
		}
		if (name == "hierarchicalObjectMap" || name == "whiskermap::maps::CHierarchicalObjectMap")
		{
			ours += static_cast<size_t>(n);
			ourName = name;
		}
	}
	// Every other section must belong to a declared map ([bogus] is an error, with its line).
	for (const auto& s : file->sectionsInOrder())
	{
		if (s == section) continue;
		if (std::none_of(prefixes.begin(), prefixes.end(), [&](const std::string& p) { return s.rfind(p, 0) == 0; }))
			throw core::Error(core::iniWhere(*file, s) + "[" + s + "]: unknown section (no map declared in [" + section +
							  "] reads it)");
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
