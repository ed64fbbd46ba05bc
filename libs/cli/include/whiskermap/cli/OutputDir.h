#pragma once
#include <whiskermap/core/OutputTransaction.h>

#include <string>

namespace whiskermap::cli
{
/** An app's output folder, written as a group through core::OutputTransaction: files are
 *  staged and moved into place by commit(); on an error, a signal or a kill the folder keeps
 *  exactly what it had before (a folder this run created is removed again). */
class OutputDir
{
   public:
	/** Throws core::Error when `dir` is empty or names something that is not a folder. */
	explicit OutputDir(const std::string& dir);

	/** Path to write `name` to (staged). */
	std::string path(const std::string& name);
	/** Moves every staged file into the output folder. */
	void commit() { m_tx.commit(); }
	/** Final location of `name`. */
	std::string finalPath(const std::string& name) const;

   private:
	std::string m_dir;
	core::OutputTransaction m_tx;
};
}  // namespace whiskermap::cli
