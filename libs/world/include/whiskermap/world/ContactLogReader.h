#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/world/ContactLogFormat.h>
#include <whiskermap/world/Robot.h>

#include <array>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace whiskermap::world
{
/** Reads a text contact log (ContactLogFormat, doc/formats.md) one sweep at a time, for a
 *  robot (its whiskers' mountings, lengths and sweeps) and the sensor noise to record.
 *
 *  Strict: the first problem throws core::Error, one line "FILE: line L, column 'NAME'
 *  (field K): problem": a bad first line, a missing, unknown or repeated column, a value that
 *  is not a number or not finite, an angle outside the whisker's sweep, r negative or past its
 *  length, texture outside [0, 1], a whisker index the robot lacks or that a sweep repeats, a
 *  sweep whose rows disagree on time or odometry or that lacks a whisker, times going
 *  backwards, no sweep at all. A sweep is handed out once its rows are all checked; a later
 *  line can still fail, so a caller writing sweeps as they come writes to a temporary file
 *  (as RawlogWriter does). Memory: one line (at most 64 KiB) and one sweep. */
class ContactLogReader
{
   public:
	struct Sweep
	{
		mrpt::poses::CPose2D odometry;				///< absolute robot pose
		obs::CObservationWhiskerContacts::Ptr obs;	///< the sweep, validated
		size_t line = 0;							///< line of its first row
	};

	ContactLogReader(const std::string& path, const Robot& robot, const obs::TSensorNoise& noise);

	/** Reads the next sweep into `out`; false at the end of the file. */
	bool next(Sweep& out);

	size_t rows() const { return m_rows; }		///< data rows read so far
	size_t sweeps() const { return m_sweeps; }	///< sweeps handed out so far

   private:
	using Column = ContactLogFormat::Column;
	/** The sweep being assembled from its rows. */
	struct Pending
	{
		obs::CObservationWhiskerContacts::Ptr obs;
		mrpt::Clock::time_point time;
		double x = 0, y = 0, yaw = 0;
		size_t line = 0, count = 0;
		std::vector<size_t> whiskerLine;  ///< line of each whisker's row, 0 if not yet seen
	};

	bool rawLine();	  ///< the next line into m_text; false at the end of the file
	bool dataLine();  ///< the next line that is not blank or a comment
	void readFirstLines();
	void splitFields();
	void readRow();
	void checkSameSweep(mrpt::Clock::time_point t, double x, double y, double yaw) const;
	void readReading(obs::TWhisker& w, size_t index);
	std::string missingWhiskers() const;
	std::string_view field(Column c) const { return m_fields[m_fieldOf[c]]; }
	double number(Column c) const;
	double degrees(Column c) const;
	[[noreturn]] void fail(Column c, const std::string& problem) const;
	[[noreturn]] void failAt(
		size_t line, const std::string& where, const std::string& problem) const;

	std::string m_path;
	Robot m_robot;
	obs::TSensorNoise m_noise;
	std::ifstream m_in;
	std::vector<char> m_buffer;
	std::string_view m_text;				 ///< the current line, without its end
	std::vector<std::string_view> m_fields;	 ///< its comma-separated fields, trimmed
	std::vector<std::string> m_header;		 ///< column name of each field
	std::array<size_t, ContactLogFormat::COLUMN_COUNT> m_fieldOf{};
	size_t m_line = 0, m_headerLine = 0, m_rows = 0, m_sweeps = 0;
	Pending m_sweep;
	mrpt::Clock::time_point m_lastTime;
	size_t m_lastLine = 0;	///< first line of the last sweep handed out (0: none yet)
};
}  // namespace whiskermap::world
