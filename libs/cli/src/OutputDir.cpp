#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/core/Error.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace whiskermap::cli
{
OutputDir::OutputDir(const std::string& dir) : m_dir(dir)
{
	if (dir.empty()) throw core::Error("the output folder name is empty (-o \"\")");
	std::error_code ec;
	if (fs::exists(dir, ec) && !fs::is_directory(dir, ec)) throw core::Error(dir + ": exists and is not a folder");
}

std::string OutputDir::path(const std::string& name) { return m_tx.stage(finalPath(name)); }

std::string OutputDir::finalPath(const std::string& name) const { return (fs::path(m_dir) / name).string(); }
}  // namespace whiskermap::cli
