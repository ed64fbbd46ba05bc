#include <fcntl.h>
#include <sys/file.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/OutputTransaction.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace whiskermap::core
{
namespace
{
const std::string PREFIX = ".whiskermap-staging-";
const int SIGNALS[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

// What the signal handler removes: fixed storage, written only with signals blocked.
constexpr int MAX_DIRS = 16, MAX_PATH = 4096;
char g_stages[MAX_DIRS][MAX_PATH], g_created[MAX_DIRS][MAX_PATH];
volatile sig_atomic_t g_nStages = 0, g_nCreated = 0;
struct sigaction g_old[4];

/** Empties and removes a flat folder with async-signal-safe calls only. */
void removeFlat(const char* dir)
{
	const int fd = ::open(dir, O_RDONLY | O_DIRECTORY);
	if (fd < 0) return;
	alignas(8) char buf[4096];
	for (;;)
	{
		const long n = ::syscall(SYS_getdents64, fd, buf, sizeof(buf));
		if (n <= 0) break;
		for (long off = 0; off < n;)
		{
			const char* name = buf + off + 19;  // struct linux_dirent64: d_ino, d_off, d_reclen, d_type, d_name
			unsigned short reclen;
			std::memcpy(&reclen, buf + off + 16, sizeof(reclen));
			if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) ::unlinkat(fd, name, 0);
			off += reclen;
		}
	}
	::close(fd);
	::rmdir(dir);
}

void onSignal(int sig)
{
	for (int i = 0; i < g_nStages; i++) removeFlat(g_stages[i]);
	for (int i = g_nCreated - 1; i >= 0; i--) ::rmdir(g_created[i]);
	::signal(sig, SIG_DFL);
	::raise(sig);
}

/** Blocks the handled signals for its scope (the registry and commit() must not be cut). */
class SignalBlock
{
   public:
	SignalBlock()
	{
		sigset_t s;
		sigemptyset(&s);
		for (int sig : SIGNALS) sigaddset(&s, sig);
		::sigprocmask(SIG_BLOCK, &s, &m_old);
	}
	~SignalBlock() { ::sigprocmask(SIG_SETMASK, &m_old, nullptr); }

   private:
	sigset_t m_old;
};

void remember(char (*list)[MAX_PATH], volatile sig_atomic_t& n, const std::string& path)
{
	if (n >= MAX_DIRS || path.size() >= MAX_PATH) throw Error(path + ": too many or too long output folders");
	SignalBlock block;
	std::strcpy(list[n], path.c_str());
	n = n + 1;
}
}  // namespace

OutputTransaction::OutputTransaction()
{
	g_nStages = g_nCreated = 0;
	struct sigaction sa{};
	sa.sa_handler = onSignal;
	sigemptyset(&sa.sa_mask);
	for (int i = 0; i < 4; i++) ::sigaction(SIGNALS[i], &sa, &g_old[i]);
}

OutputTransaction::~OutputTransaction()
{
	if (!m_done) rollback();
	for (int i = 0; i < 4; i++) ::sigaction(SIGNALS[i], &g_old[i], nullptr);
	g_nStages = g_nCreated = 0;
}

void OutputTransaction::cleanStale(const std::string& dir)
{
	std::error_code ec;
	const std::string mine = PREFIX + std::to_string(::getpid());
	for (const auto& e : fs::directory_iterator(dir, ec))
	{
		const std::string name = e.path().filename().string();
		if (name.rfind(PREFIX, 0) != 0 || name == mine) continue;
		const int fd = ::open((e.path() / ".lock").c_str(), O_RDWR);
		if (fd >= 0 && ::flock(fd, LOCK_EX | LOCK_NB) != 0)
		{
			::close(fd);  // a live run holds it
			continue;
		}
		if (fd < 0)
		{
			// No lock yet: stale only when its process is gone.
			const auto pid = std::atol(name.c_str() + PREFIX.size());
			if (pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)) continue;
		}
		// Killed during commit: finish the moves its journal lists.
		std::ifstream journal(e.path() / ".journal");
		for (std::string file; std::getline(journal, file);)
			if (!file.empty() && fs::exists(e.path() / file, ec)) fs::rename(e.path() / file, fs::path(dir) / file, ec);
		fs::remove_all(e.path(), ec);
		if (fd >= 0) ::close(fd);
	}
}

OutputTransaction::Folder& OutputTransaction::folderFor(const std::string& dir)
{
	for (auto& f : m_folders)
		if (f.dir == dir) return f;
	cleanStale(dir);
	Folder f{dir, (fs::path(dir) / (PREFIX + std::to_string(::getpid()))).string()};
	std::error_code ec;
	fs::remove_all(f.stage, ec);  // ours from an earlier transaction of this process
	if (!fs::create_directory(f.stage, ec)) throw Error(dir + ": cannot write in output folder (" + ec.message() + ")");
	remember(g_stages, g_nStages, f.stage);
	f.lockFd = ::open((fs::path(f.stage) / ".lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
	if (f.lockFd < 0 || ::flock(f.lockFd, LOCK_EX) != 0) throw Error(dir + ": cannot lock staging folder");
	m_folders.push_back(f);
	return m_folders.back();
}

std::string OutputTransaction::stage(const std::string& finalPath)
{
	if (finalPath.empty()) throw Error("an output path is empty");
	const fs::path p(finalPath);
	std::error_code ec;
	if (fs::is_directory(p, ec)) throw Error(finalPath + ": is a folder, not a file");
	if (p.filename().empty() || p.filename() == "." || p.filename() == "..")
		throw Error(finalPath + ": not a file name");
	const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
	// Create missing folders, outermost first, remembering them to remove on failure.
	std::vector<fs::path> missing;
	for (fs::path d = dir; !d.empty() && !fs::exists(d, ec); d = d.parent_path()) missing.push_back(d);
	for (auto it = missing.rbegin(); it != missing.rend(); ++it)
	{
		if (!fs::create_directory(*it, ec))
			throw Error(it->string() + ": cannot create output folder (" + ec.message() + ")");
		m_created.push_back(it->string());
		remember(g_created, g_nCreated, it->string());
	}
	if (!fs::is_directory(dir, ec)) throw Error(dir.string() + ": not a folder");
	const Folder& f = folderFor(dir.string());
	const std::string staged = (fs::path(f.stage) / p.filename()).string();
	for (const auto& s : m_files)
		if (s.staged == staged) return staged;
	m_files.push_back({staged, finalPath});
	return staged;
}

void OutputTransaction::commit()
{
	SignalBlock block;
	std::error_code ec;
	for (const auto& f : m_folders)
	{
		std::ofstream journal(fs::path(f.stage) / ".journal.tmp");
		for (const auto& s : m_files)
			if (fs::path(s.staged).parent_path() == f.stage && fs::exists(s.staged, ec))
				journal << fs::path(s.staged).filename().string() << "\n";
		journal.close();
		if (!journal) throw Error(f.dir + ": cannot write the commit journal");
		fs::rename(fs::path(f.stage) / ".journal.tmp", fs::path(f.stage) / ".journal");
	}
	for (const auto& s : m_files)
		if (fs::exists(s.staged, ec))
		{
			fs::rename(s.staged, s.final, ec);
			if (ec) throw Error(s.final + ": cannot move into place (" + ec.message() + ")");
		}
	for (auto& f : m_folders)
	{
		fs::remove_all(f.stage, ec);
		if (f.lockFd >= 0) ::close(f.lockFd), f.lockFd = -1;
	}
	m_done = true;
	g_nStages = g_nCreated = 0;
}

void OutputTransaction::rollback()
{
	SignalBlock block;
	std::error_code ec;
	for (auto& f : m_folders)
	{
		fs::remove_all(f.stage, ec);
		if (f.lockFd >= 0) ::close(f.lockFd), f.lockFd = -1;
	}
	for (auto it = m_created.rbegin(); it != m_created.rend(); ++it) fs::remove(*it, ec);  // only if empty
	g_nStages = g_nCreated = 0;
}
}  // namespace whiskermap::core
