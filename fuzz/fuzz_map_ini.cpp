// Fuzz target: CMultiMetricMap .ini files as whisker-map reads them (MapConfig::load, then
// the maps built from them, as the app does). Only core::Error may refuse bad input.
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		mrpt::maps::CMultiMetricMap multimap(whiskermap::maps::MapConfig::load(fuzzFile(data, size, ".ini")));
		(void)multimap.mapByClass<whiskermap::maps::CHierarchicalObjectMap>();
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
