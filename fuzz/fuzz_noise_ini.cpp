// Fuzz target: noise preset .ini files (NoisePreset::load with a path). Only core::Error may
// refuse bad input.
#include <whiskermap/core/Error.h>
#include <whiskermap/world/NoisePreset.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		whiskermap::world::NoisePreset::load(fuzzFile(data, size, ".ini"));
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
