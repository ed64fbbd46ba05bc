// Fuzz target: odometry noise .ini files (OdometryNoise::load with a path, whisker-sim
// --odometry FILE). Only core::Error may refuse bad input.
#include <whiskermap/core/Error.h>
#include <whiskermap/world/OdometryNoise.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		whiskermap::world::OdometryNoise::load(fuzzFile(data, size, ".ini"));
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
