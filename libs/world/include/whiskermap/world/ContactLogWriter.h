#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <fstream>
#include <string>

namespace whiskermap::world
{
/** Writes whisker sweeps with their robot poses as a text contact log (ContactLogFormat,
 *  doc/formats.md): one row per whisker per sweep, every number in the fewest digits that
 *  ContactLogReader reads back to the same bits. Untouched whiskers are written with the
 *  readings they carry (the reader ignores them and restores Robot::blankSweep's).
 *
 *  A contact log holds one sensor: every sweep must have the first one's label, sensor pose,
 *  noise and whisker mountings (the reader takes those from the robot .ini and the noise
 *  preset), and times must not go backwards; otherwise write() throws core::Error naming
 *  `source` and the sweep. The file is written under a temporary name and renamed by close(). */
class ContactLogWriter
{
   public:
	/** `source` names where the sweeps come from, in the file's comments and in errors. */
	ContactLogWriter(const std::string& path, const std::string& source);
	~ContactLogWriter();  ///< removes the temporary file if close() was not reached

	void write(const mrpt::poses::CPose2D& odometry, const obs::CObservationWhiskerContacts& sweep);
	/** Flushes and renames the file into place; throws if no sweep was written. */
	void close();

	size_t rows() const { return m_rows; }
	size_t sweeps() const { return m_sweeps; }

   private:
	void writeHeader(const obs::CObservationWhiskerContacts& first);
	void checkSameSensor(const obs::CObservationWhiskerContacts& sweep) const;

	std::string m_path, m_source;
	std::ofstream m_out;
	obs::CObservationWhiskerContacts m_first;  ///< the sensor every sweep must match
	mrpt::Clock::time_point m_lastTime;
	std::string m_row;
	size_t m_rows = 0, m_sweeps = 0;
	bool m_closed = false;
};
}  // namespace whiskermap::world
