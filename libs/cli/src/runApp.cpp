#include <CLI/CLI.hpp>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/conciseMessage.h>

#include <iostream>

namespace whiskermap::cli
{
int runApp(CLI::App& app, int argc, char** argv, const std::string& name, const std::function<int()>& run)
{
	try
	{
		app.parse(argc, argv);
		return run();
	}
	catch (const CLI::ParseError& e)
	{
		return app.exit(e);
	}
	catch (const std::exception& e)
	{
		std::cerr << name << ": error: " << core::conciseMessage(e) << "\n";
		return 1;
	}
}
}  // namespace whiskermap::cli
