// Fuzz target: robot .ini files (Robot::load). Bad input may only be refused with core::Error.
#include <whiskermap/core/Error.h>
#include <whiskermap/world/Robot.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		whiskermap::world::Robot::load(fuzzFile(data, size, ".ini"));
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
