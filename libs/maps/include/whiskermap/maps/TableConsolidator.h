#pragma once
#include <whiskermap/maps/TMapObject.h>
#include <whiskermap/obs/Shapelet.h>

#include <vector>

namespace whiskermap::maps
{
/** Builds the consolidated object map from per-pose MAP tables: a table within the
 *  position and yaw gates (yaw modulo 180 degrees) of an object merges into the nearest
 *  such object; otherwise it starts a new one. Order-dependent by nature, and deterministic. */
class TableConsolidator
{
   public:
	struct TOptions
	{
		double merge_distance = 0.15;  ///< metres between centres
		double merge_angle = 0.26;  ///< radians (15 degrees), modulo 180 degrees
		/** A contact counts as evidence on an object within this distance of one of its legs. */
		double evidence_margin = 0.05;
	};

	TableConsolidator() = default;
	explicit TableConsolidator(const TOptions& o) : m_opts(o) {}

	/** Adds one pose's MAP tables; `shapelets` (the pose's own contacts) count evidence. */
	void addPose(const std::vector<world::Table>& tables, const std::vector<obs::Shapelet>& shapelets);

	const std::vector<TMapObject>& objects() const { return m_objects; }
	std::vector<TMapObject>& objects() { return m_objects; }
	const TOptions& options() const { return m_opts; }
	void setOptions(const TOptions& o) { m_opts = o; }
	void clear() { m_objects.clear(); }

   private:
	TOptions m_opts;
	std::vector<TMapObject> m_objects;
};
}  // namespace whiskermap::maps
