#pragma once
#include <fstream>
#include <string>

namespace whiskermap::core
{
/** Reads a text file line by line in bounded memory: a line longer than `maxLine` bytes,
 *  or holding a NUL or other control byte (tab and a final CR excepted), is a core::Error
 *  "FILE: line N: problem". For every text input (path files, CSV tables). */
class LineReader
{
   public:
	/** Throws core::Error when `path` is not a readable regular file. */
	LineReader(const std::string& path, const std::string& kind, size_t maxLine = 4096);

	/** The next line without its end of line; false at the end of the file. */
	bool next(std::string& line);
	/** Number of the line last returned (1-based). */
	size_t lineNo() const { return m_line; }
	/** "FILE: line N: " for error messages about the current line. */
	std::string where() const;

   private:
	std::string m_path;
	std::ifstream m_in;
	size_t m_max, m_line = 0;
};
}  // namespace whiskermap::core
