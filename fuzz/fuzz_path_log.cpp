// Fuzz target: timestamped path files (world::PathLog: whisker-eval --path and --truth,
// whisker-slam --truth), streamed and scored against themselves as whisker-eval would.
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TrajectoryEvaluation.h>
#include <whiskermap/world/PathLog.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		const std::string file = fuzzFile(data, size, ".txt");
		whiskermap::world::PathLog::Reader r(file);
		for (whiskermap::world::PathLog::Entry e; r.next(e);)
		{
		}
		whiskermap::eval::TrajectoryEvaluation::compute(file, file, whiskermap::eval::EvalOptions{});
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
