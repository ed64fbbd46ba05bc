// Fuzz target: the table CSV readers (map_tables.csv, per_pose_tables.csv, map_walls.csv);
// the first byte chooses which (odd: map; else bit 1: walls, or per-pose), the rest is the file.
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TableCsv.h>

#include "TempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	if (size == 0) return 0;
	using whiskermap::eval::TableCsv;
	try
	{
		const auto& path = fuzzFile(data + 1, size - 1, ".csv");
		if (data[0] & 1)
			TableCsv::tables(TableCsv::readMap(path));
		else if (data[0] & 2)
			TableCsv::readWalls(path);
		else
		{
			TableCsv::PerPoseReader r(path, 1u << 30);
			std::vector<whiskermap::world::Table> tables;
			for (int i = 0; i < 1000 && r.next(tables); i++)
			{
			}
		}
	}
	catch (const whiskermap::core::Error&)
	{
	}
	return 0;
}
