#pragma once
#include <whiskermap/core/IniFile.h>
#include <whiskermap/world/World.h>

#include <string>
#include <vector>

namespace whiskermap::world::detail
{
/** Reads the [wall_N] sections of a world file, in order of N, into w.walls (the arena
 *  already read); returns their section names. */
std::vector<std::string> readWalls(const core::IniFile& cfg, const std::string& path, World& w);
/** Reads the [table_N] sections, in order of N, into w.tables (arena and walls already read;
 *  `wallNames` name w.walls in errors). */
void readTables(
	const core::IniFile& cfg, const std::string& path, const std::vector<std::string>& wallNames,
	World& w);
}  // namespace whiskermap::world::detail
