#pragma once
#include <whiskermap/maps/TPoseRecord.h>

#include <cstdio>
#include <string>

namespace whiskermap::maps
{
/** Writes per_pose_tables.csv (MapCsv's format) one pose at a time, for streaming runs:
 *  rows go to a temporary file, renamed by close(); without close() it is removed. */
class PerPoseCsvWriter
{
   public:
	explicit PerPoseCsvWriter(const std::string& path);
	~PerPoseCsvWriter();
	PerPoseCsvWriter(const PerPoseCsvWriter&) = delete;
	PerPoseCsvWriter& operator=(const PerPoseCsvWriter&) = delete;

	/** The rows of pose `index` (none if it found no table). */
	void add(size_t index, const TPoseRecord& pose);
	void close();

   private:
	std::string m_path;
	FILE* m_file = nullptr;
};
}  // namespace whiskermap::maps
