#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

namespace whiskermap::core
{
std::string ConfigPaths::find(const std::string& rel)
{
	std::vector<std::string> dirs;
	if (const char* env = std::getenv("WHISKERMAP_CONFIG_DIR")) dirs.push_back(env);
	dirs.push_back(WHISKERMAP_SOURCE_CONFIG_DIR);
	dirs.push_back(WHISKERMAP_INSTALL_CONFIG_DIR);
	std::string tried;
	for (const auto& d : dirs)
	{
		const auto p = std::filesystem::path(d) / rel;
		if (std::filesystem::is_regular_file(p)) return p.string();
		tried += (tried.empty() ? "" : ", ") + p.string();
	}
	throw Error(rel + ": no such shipped config file (looked in " + tried + ")");
}

std::string ConfigPaths::resolve(const std::string& arg, const std::string& subdir)
{
	if (std::filesystem::is_regular_file(arg)) return arg;
	if (arg.find('/') != std::string::npos || arg.find(".ini") != std::string::npos)
		throw Error(arg + ": no such file");
	return find(subdir + "/" + arg + ".ini");
}
}  // namespace whiskermap::core
