// Fuzz target: whisker-sim path files (Trajectory::pathFileSource, then every pose).
#include <whiskermap/core/Error.h>
#include <whiskermap/world/Trajectory.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		auto src = whiskermap::world::Trajectory::pathFileSource(fuzzFile(data, size, ".path"));
		mrpt::poses::CPose2D p;
		while (src->next(p))
		{
		}
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
