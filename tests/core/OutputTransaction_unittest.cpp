// Regression tests of issue 8: outputs were not atomic as a group (earlier files replaced
// before a later one failed; a killed run left .staging-PID or *.tmp behind).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/OutputTransaction.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <set>

using whiskermap::core::OutputTransaction;
namespace fs = std::filesystem;

namespace
{
class OutputTransactionTest : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		dir = fs::temp_directory_path() / ("whiskermap_tx_" + std::to_string(::getpid()) + "_" +
										   ::testing::UnitTest::GetInstance()->current_test_info()->name());
		fs::remove_all(dir);
		fs::create_directories(dir / "out");
		std::ofstream(dir / "out" / "a.txt") << "old a";
	}
	void TearDown() override { fs::remove_all(dir); }
	std::set<std::string> listing(const fs::path& d) const
	{
		std::set<std::string> names;
		for (const auto& e : fs::directory_iterator(d)) names.insert(e.path().filename().string());
		return names;
	}
	static std::string slurp(const fs::path& p)
	{
		std::ifstream f(p);
		return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	}
	/** Runs `body` in a child process and returns its wait status. */
	template <class F>
	static int inChild(F body)
	{
		const pid_t pid = ::fork();
		if (pid == 0)
		{
			body();
			::_exit(0);
		}
		int status = 0;
		::waitpid(pid, &status, 0);
		return status;
	}
	fs::path dir;
};
}  // namespace

TEST_F(OutputTransactionTest, CommitMovesEveryFileAtOnce)
{
	OutputTransaction tx;
	std::ofstream(tx.stage((dir / "out" / "a.txt").string())) << "new a";
	std::ofstream(tx.stage((dir / "out" / "b.txt").string())) << "new b";
	EXPECT_EQ(slurp(dir / "out" / "a.txt"), "old a");  // nothing moved before commit
	tx.commit();
	EXPECT_EQ(slurp(dir / "out" / "a.txt"), "new a");
	EXPECT_EQ(listing(dir / "out"), (std::set<std::string>{"a.txt", "b.txt"}));
}

TEST_F(OutputTransactionTest, AnErrorLeavesEveryFolderAsItWas)
{
	{
		OutputTransaction tx;
		std::ofstream(tx.stage((dir / "out" / "a.txt").string())) << "new a";
		std::ofstream(tx.stage((dir / "new" / "deeper" / "c.txt").string())) << "c";
	}  // destroyed without commit: an error
	EXPECT_EQ(slurp(dir / "out" / "a.txt"), "old a");
	EXPECT_EQ(listing(dir / "out"), std::set<std::string>{"a.txt"});
	EXPECT_FALSE(fs::exists(dir / "new"));  // folders it created are gone too
}

TEST_F(OutputTransactionTest, BadPathsAreRefused)
{
	OutputTransaction tx;
	EXPECT_THROW(tx.stage(""), whiskermap::core::Error);
	EXPECT_THROW(tx.stage((dir / "out").string()), whiskermap::core::Error);  // a folder
	EXPECT_THROW(tx.stage((dir / "out" / "a.txt" / "x").string()), whiskermap::core::Error);  // under a file
}

TEST_F(OutputTransactionTest, ATerminatedRunLeavesNothing)
{
	for (const int sig : {SIGTERM, SIGINT, SIGHUP})
	{
		const int status = inChild([&] {
			OutputTransaction tx;
			std::ofstream(tx.stage((dir / "out" / "a.txt").string())) << "new a";
			std::ofstream(tx.stage((dir / "out" / "a.txt").string() + ".tmp")) << "half";
			std::ofstream(tx.stage((dir / "made" / "b.txt").string())) << "b";
			::raise(sig);
		});
		EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << sig;
		EXPECT_EQ(listing(dir / "out"), std::set<std::string>{"a.txt"}) << sig;
		EXPECT_EQ(slurp(dir / "out" / "a.txt"), "old a");
		EXPECT_FALSE(fs::exists(dir / "made")) << sig;
	}
}

TEST_F(OutputTransactionTest, AKilledRunsLeftoversAreCleanedByTheNextRun)
{
	const int status = inChild([&] {
		OutputTransaction tx;
		std::ofstream(tx.stage((dir / "out" / "a.txt").string())) << "new a";
		::raise(SIGKILL);
	});
	EXPECT_TRUE(WIFSIGNALED(status));
	EXPECT_EQ(listing(dir / "out").size(), 2u);  // a.txt and the dead run's staging folder
	{
		OutputTransaction tx;
		std::ofstream(tx.stage((dir / "out" / "b.txt").string())) << "b";
		tx.commit();
	}
	EXPECT_EQ(listing(dir / "out"), (std::set<std::string>{"a.txt", "b.txt"}));
	EXPECT_EQ(slurp(dir / "out" / "a.txt"), "old a");
}

TEST_F(OutputTransactionTest, AKillDuringCommitIsCompletedByTheNextRun)
{
	// A staging folder as a commit killed after its journal leaves it: the next run
	// completes the moves the journal lists.
	const fs::path stage = dir / "out" / ".whiskermap-staging-999999999";
	fs::create_directories(stage);
	std::ofstream(stage / "a.txt") << "new a";
	std::ofstream(stage / ".journal") << "a.txt\n";
	OutputTransaction::cleanStale((dir / "out").string());
	EXPECT_EQ(listing(dir / "out"), std::set<std::string>{"a.txt"});
	EXPECT_EQ(slurp(dir / "out" / "a.txt"), "new a");
}
