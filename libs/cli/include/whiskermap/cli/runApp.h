#pragma once
#include <functional>
#include <string>

namespace CLI
{
class App;
}

namespace whiskermap::cli
{
/** Parses the command line into `app`'s options, then calls `run`. Usage errors print
 *  CLI11's message (and --help its help) with CLI11's exit code; any other error prints one
 *  line, "<name>: error: <message>" (MRPT's multi-line messages reduced to their cause),
 *  and returns 1. */
int runApp(CLI::App& app, int argc, char** argv, const std::string& name, const std::function<int()>& run);
}  // namespace whiskermap::cli
