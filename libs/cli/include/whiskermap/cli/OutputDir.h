#pragma once
#include <string>
#include <vector>

namespace whiskermap::cli
{
/** Writes a set of output files atomically as a group: files go to a hidden staging folder
 *  inside the output folder and are moved into place by commit(); if commit() is never
 *  reached (an error), the staging folder is removed and the output folder keeps exactly
 *  what it had before. */
class OutputDir
{
   public:
	explicit OutputDir(const std::string& dir);  ///< creates dir if needed; throws core::Error
	~OutputDir();

	/** Path to write `name` to (inside the staging folder). */
	std::string path(const std::string& name);
	/** Moves every staged file into the output folder. */
	void commit();
	/** Final location of `name`. */
	std::string finalPath(const std::string& name) const;

   private:
	std::string m_dir, m_stage;
	std::vector<std::string> m_names;
};
}  // namespace whiskermap::cli
