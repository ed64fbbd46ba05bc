// Fuzz target: text contact logs (ContactLogReader, what whisker-import reads) for the shipped
// scratchbot robot, every sweep read to the end. Only core::Error may refuse bad input.
#include <whiskermap/core/Error.h>
#include <whiskermap/world/ContactLogReader.h>
#include <whiskermap/world/Robot.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	using namespace whiskermap::world;
	static const Robot robot = Robot::load(WHISKERMAP_SOURCE_DIR "/config/robots/scratchbot.ini");
	try
	{
		ContactLogReader reader(fuzzFile(data, size, ".csv"), robot, whiskermap::obs::TSensorNoise());
		ContactLogReader::Sweep sweep;
		while (reader.next(sweep))
		{
		}
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
