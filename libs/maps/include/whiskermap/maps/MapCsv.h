#pragma once
#include <whiskermap/maps/TMappedObject.h>
#include <whiskermap/maps/TPoseRecord.h>
#include <whiskermap/model/LastingState.h>

#include <string>
#include <vector>

namespace whiskermap::maps
{
/** The map's CSV outputs (doc/outputs.md). Metres and degrees; written via a temporary file
 *  renamed when complete. Throws core::Error when a file cannot be written. */
struct MapCsv
{
	/** `id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs`, one row per
	 *  object (id = its row index); with `withSpread` (the lasting map) then
	 *  `,sd_x,sd_y,sd_yaw_deg` (an object without its spread is a core::Error); with `withClass` (a map
	 *  with an object catalogue) last `,class` (the column whisker-eval matches classes by). */
	static void writeObjects(
		const std::string& path, const std::vector<TMappedObject>& objects, bool withClass = false,
		bool withSpread = false);
	/** `pose,x,y,yaw_deg,length,width,leg_width,texture,log_posterior`, one row per MAP table
	 *  per pose (pose = 0-based index of the sweep; poses without tables have no row). */
	/** `x0,y0,x1,y1,thickness,existence`, one row per wall (the format whisker-eval --walls
	 *  reads; doc/formats.md). */
	static void writeWalls(const std::string& path, const std::vector<model::LastingState::StoredWall>& walls);
	static void writePerPose(const std::string& path, const std::vector<TPoseRecord>& poses);
};
}  // namespace whiskermap::maps
