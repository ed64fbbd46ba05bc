#pragma once
#include <whiskermap/world/RawlogWriter.h>

#include <string>

namespace CLI
{
class App;
}

namespace whiskermap::cli
{
/** The `--format obs|action-sf` option of the apps that write rawlogs (whisker-sim,
 *  whisker-import). */
struct RawlogFormatOption
{
	static void add(CLI::App& app, std::string& value);
	static world::RawlogWriter::Format parse(const std::string& value);
};
}  // namespace whiskermap::cli
