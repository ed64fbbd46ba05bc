#pragma once
#include <mrpt/core/Clock.h>

#include <array>
#include <string>
#include <string_view>

namespace whiskermap::world
{
/** The text contact log, version 1 (doc/formats.md, "Contact logs"): its first line, its
 *  columns, and the number conversions shared by ContactLogReader and ContactLogWriter.
 *
 *  The conversions are exact, so an export followed by an import gives back every bit:
 *  - times are decimal seconds (UNIX epoch) read without floating point, to MRPT's 100 ns tick;
 *  - plain numbers are written as the shortest text that reads back to the same double;
 *  - degrees are read as "the decimal rounded to long double, times pi/180 in long double,
 *    rounded to double" (extended precision makes every radian value reachable, which a
 *    double-precision degree value cannot), and written as the shortest text that reads
 *    back, by that rule, to the same radians.
 *  Parsers return nullptr on success, else the reason ("is not a number", ...). */
struct ContactLogFormat
{
	/** The first line of every contact log; the version is its last word. */
	static constexpr std::string_view FIRST_LINE = "# whiskermap contacts v1";

	enum Column
	{
		TIME,
		ODOM_X,
		ODOM_Y,
		ODOM_YAW_DEG,
		WHISKER,
		TOUCHED,
		ANGLE_DEG,
		R,
		NORMAL_DEG,
		TEXTURE,
		COLUMN_COUNT
	};
	/** Column names, in the order the writer uses (a reader accepts any order). */
	static constexpr std::array<std::string_view, COLUMN_COUNT> COLUMNS = {
		"time",	   "odom_x",	"odom_y", "odom_yaw_deg", "whisker",
		"touched", "angle_deg", "r",	  "normal_deg",	  "texture"};

	/** A finite number (a leading '+' is allowed). */
	static const char* parseNumber(std::string_view s, double& out);
	/** Degrees, finite, to radians by the exact rule above. */
	static const char* parseDegrees(std::string_view s, double& radians);
	/** Seconds since the UNIX epoch, rounded to the nearest 100 ns tick; at most 19
	 *  significant digits (nanosecond stamps fit). */
	static const char* parseTime(std::string_view s, mrpt::Clock::time_point& out);

	static void appendNumber(std::string& out, double v);
	static void appendDegrees(std::string& out, double radians);
	static void appendTime(std::string& out, mrpt::Clock::time_point t);
};
}  // namespace whiskermap::world
