#include <unistd.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/core/Error.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace whiskermap::cli
{
OutputDir::OutputDir(const std::string& dir)
	: m_dir(dir), m_stage((fs::path(dir) / (".staging-" + std::to_string(::getpid()))).string())
{
	std::error_code ec;
	fs::create_directories(m_stage, ec);
	if (ec) throw core::Error(dir + ": cannot create output folder (" + ec.message() + ")");
}

OutputDir::~OutputDir()
{
	std::error_code ec;
	fs::remove_all(m_stage, ec);
}

std::string OutputDir::path(const std::string& name)
{
	m_names.push_back(name);
	return (fs::path(m_stage) / name).string();
}

std::string OutputDir::finalPath(const std::string& name) const { return (fs::path(m_dir) / name).string(); }

void OutputDir::commit()
{
	for (const auto& n : m_names)
		if (fs::exists(fs::path(m_stage) / n)) fs::rename(fs::path(m_stage) / n, finalPath(n));
}
}  // namespace whiskermap::cli
