#pragma once
#include <mrpt/maps/TMetricMapInitializer.h>

#include <string>

namespace whiskermap::maps
{
/** Loads a CMultiMetricMap .ini ([MetricMap] with `<mapName>_count=N`, then the maps'
 *  sections) strictly. MRPT alone silently makes zero maps for an unknown name, and ignores
 *  misspelt keys; here both are errors (core::Error, one line naming file, section, key),
 *  as is a file that defines no hierarchicalObjectMap. */
struct MapConfig
{
	static mrpt::maps::TSetOfMetricMapInitializers load(const std::string& path);
};
}  // namespace whiskermap::maps
