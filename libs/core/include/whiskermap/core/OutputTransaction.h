#pragma once
#include <string>
#include <vector>

namespace whiskermap::core
{
/** Output files committed as a group (doc/outputs.md, "Outputs are all or nothing").
 *
 *  stage(final) gives the path to write `final` to: a hidden staging folder
 *  `.whiskermap-staging-<pid>` inside final's folder (same file system, so the move is a
 *  rename). commit() moves every staged file into place; until then no destination is
 *  touched. Whatever stops the run first leaves every output folder as it was:
 *  - an error (the transaction destroyed without commit): staging folders removed, and any
 *    output folder this transaction created removed again;
 *  - SIGINT, SIGTERM, SIGHUP, SIGQUIT: the same, from the signal handler, then the signal's
 *    default action (commit() blocks them while it moves files, so a commit is never cut);
 *  - SIGKILL or a crash: the staging folder stays, holding a lock that dies with the
 *    process; the next transaction staging into that folder removes it (or, if the kill
 *    came during commit, first completes the moves its journal lists).
 *  One transaction per process at a time. Throws core::Error naming the path on failure. */
class OutputTransaction
{
   public:
	OutputTransaction();
	~OutputTransaction();
	OutputTransaction(const OutputTransaction&) = delete;
	OutputTransaction& operator=(const OutputTransaction&) = delete;

	/** Where to write the file whose final path is `finalPath` (its folder is created if
	 *  missing, and removed again on failure). Refuses an empty path or an existing folder. */
	std::string stage(const std::string& finalPath);
	/** Moves every staged file that was written into place. */
	void commit();
	/** Removes leftovers of dead runs in `dir` (done by stage() for each folder). */
	static void cleanStale(const std::string& dir);

   private:
	struct Staged
	{
		std::string staged, final;
	};
	struct Folder
	{
		std::string dir, stage;
		int lockFd = -1;
	};
	Folder& folderFor(const std::string& dir);
	void rollback();

	std::vector<Folder> m_folders;
	std::vector<Staged> m_files;
	std::vector<std::string> m_created;  ///< folders this transaction created, outermost first
	bool m_done = false;
};
}  // namespace whiskermap::core
