// Fuzz target: world .ini files (World::load). Bad input may only be refused with core::Error.
#include <whiskermap/core/Error.h>
#include <whiskermap/world/World.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		whiskermap::world::World::load(fuzzFile(data, size, ".ini")).obstacles();
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
