#pragma once
#include <whiskermap/world/Table.h>
#include <whiskermap/world/Wall.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace whiskermap::eval
{
/** Strict readers of the table CSVs whisker-map writes (doc/evaluation.md): the header must
 *  match exactly, every row has exactly its columns, every value is a finite number in range
 *  (integers where counts or indices are), lines at most 4096 bytes without control bytes.
 *  Errors are core::Error, one line naming the file
 *  and line: "map_tables.csv: line 4: column 'x': 'abc' is not a number". */
class TableCsv
{
   public:
	static constexpr const char* MAP_HEADER =
		"id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs";
	/** The same with the objects' classes (issue 11): a map without it holds tables. */
	static constexpr const char* MAP_HEADER_CLASS =
		"id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs,class";
	/** The lasting map's: with its objects' pose spreads, and their classes if any. */
	static constexpr const char* MAP_HEADER_SPREAD =
		"id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs,sd_x,sd_y,sd_yaw_deg";
	static constexpr const char* MAP_HEADER_SPREAD_CLASS =
		"id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs,sd_x,sd_y,sd_yaw_deg,class";
	/** `map_walls.csv`: one estimated wall per row (centre line end points, metres). */
	static constexpr const char* WALLS_HEADER = "x0,y0,x1,y1,thickness,existence";
	static constexpr const char* PER_POSE_HEADER =
		"pose,x,y,yaw_deg,length,width,leg_width,texture,log_posterior";

	/** One object of a map. */
	struct MapRow
	{
		long id = 0;
		world::Table table;
		double existence = 0;  ///< in [0, 1]
		uint64_t contacts = 0;  ///< contacts its legs explain
		uint32_t legs = 0;  ///< legs with a contact, 0..4
		/** The pose's standard deviations (the lasting map's spread columns). */
		struct Spread
		{
			double x = 0, y = 0, yaw_deg = 0;  ///< metres, metres, degrees
		};
		std::optional<Spread> spread;  ///< when the file has the spread columns
	};

	/** `map_tables.csv` (or `map_candidates.csv`), with or without the spread columns
	 *  (`sd_x,sd_y,sd_yaw_deg`, after `legs`) and with or without the class column last (a
	 *  class: 1 to 31 letters, digits or _; `hasClass`, if given, tells which). Ids must be
	 *  distinct. */
	static std::vector<MapRow> readMap(const std::string& path, bool* hasClass = nullptr);

	/** One estimated wall of `map_walls.csv`. */
	struct WallRow
	{
		world::Wall wall;  ///< texture unused (0)
		double existence = 0;  ///< in [0, 1]
	};
	/** `map_walls.csv`: a wall of zero length is an error. */
	static std::vector<WallRow> readWalls(const std::string& path);

	/** `per_pose_tables.csv` one pose at a time, in bounded memory: rows must come in pose
	 *  order (as whisker-map writes them); a pose index out of [0, poses) or out of order is
	 *  an error naming its line. */
	class PerPoseReader
	{
	   public:
		PerPoseReader(const std::string& path, size_t poses);
		~PerPoseReader();
		/** The tables of the next pose (0, 1, ..., poses - 1); false after the last. */
		bool next(std::vector<world::Table>& tables);

	   private:
		struct Impl;
		std::unique_ptr<Impl> m;
	};

	/** All of `per_pose_tables.csv`: element i holds the tables of pose i (memory grows
	 *  with the poses: tests and small files; apps use PerPoseReader). */
	static std::vector<std::vector<world::Table>> readPerPose(
		const std::string& path, size_t poses);

	/** The tables of the rows, in row order. */
	static std::vector<world::Table> tables(const std::vector<MapRow>& rows);
};
}  // namespace whiskermap::eval
