#pragma once
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/core/LineReader.h>

#include <fstream>
#include <string>
#include <cstdint>
#include <vector>

namespace whiskermap::world
{
/** A timestamped robot path file, one line per whisker sweep: `timestamp x y yaw` (seconds,
 *  metres, radians), `%` comment lines on top. whisker-sim writes the true path in it
 *  (`<name>_ground_truth_robot_path.txt`, as MRPT's simulators do) and, with noisy odometry,
 *  the odometry path (`<name>_odometry_path.txt`); whisker-eval --path reads an estimated
 *  path in the same columns (doc/formats.md). */
struct PathLog
{
	struct Entry
	{
		double t = 0;  ///< seconds
		mrpt::math::TPose2D pose;  ///< 24 bytes (an MRPT CPose2D, with its cached sine and cosine, takes 136)
		int line = 0;  ///< line in the file it was read from (0 if not read)
	};

	/** Reads a path file strictly: blank lines and lines starting with `%` or `#` are
	 *  skipped; every other line holds exactly four finite numbers; timestamps never go
	 *  backwards; at least one pose; no line over 4,096 bytes or holding a control byte
	 *  (core::LineReader). Throws core::Error "FILE: line L: problem". */
	static std::vector<Entry> read(const std::string& path);

	/** Checks the first `limit` poses of a path file (every line up to them) and returns how
	 *  many it holds, at most `limit`. */
	static size_t count(const std::string& path, size_t limit = SIZE_MAX);

	/** Reads a path file one pose at a time, with read()'s checks (memory: one line). */
	class Reader
	{
	   public:
		explicit Reader(const std::string& path);  ///< throws core::Error when it cannot be opened
		/** The next pose; false at the end of the file (after at least one pose: a file with
		 *  none throws). Throws core::Error "FILE: line L: problem". */
		bool next(Entry& e);
		size_t count() const { return m_count; }  ///< poses read so far

	   private:
		std::string m_path;
		core::LineReader m_in;
		size_t m_count = 0;
		double m_lastT = 0;
	};

	/** The two header lines: `% <title>` and the column line. */
	static std::string header(const std::string& title);
	/** One line, "%.6f %.9f %.9f %.9f\n" (microseconds, nanometres, nanoradians). */
	static std::string line(double t, const mrpt::poses::CPose2D& pose);

	/** Writes a path file under a temporary name; close() renames it into place, and a
	 *  writer destroyed before close() removes it (no half-written file is left). */
	class Writer
	{
	   public:
		Writer(const std::string& path, const std::string& title);  ///< throws core::Error
		~Writer();
		void write(double t, const mrpt::poses::CPose2D& pose);
		void close();  ///< throws core::Error when the write failed

	   private:
		std::string m_path;
		std::ofstream m_out;
		bool m_closed = false;
	};
};
}  // namespace whiskermap::world
