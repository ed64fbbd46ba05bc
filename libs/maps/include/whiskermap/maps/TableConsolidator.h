#pragma once
#include <whiskermap/maps/TMapObject.h>
#include <whiskermap/obs/Shapelet.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace whiskermap::maps
{
/** Builds the consolidated object map from per-pose MAP tables: a table within the
 *  position and yaw gates (yaw modulo 180 degrees) of an object merges into the nearest
 *  such object; otherwise it starts a new one. Order-dependent by nature, and deterministic.
 *  Objects are indexed on a uniform grid of their centres, so a pose costs the same however
 *  large the map grows. */
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
	/** Replaces all objects (deserialization). */
	void setObjects(std::vector<TMapObject> objects);
	const TOptions& options() const { return m_opts; }
	void setOptions(const TOptions& o) { m_opts = o; }
	void clear() { setObjects({}); }

   private:
	static constexpr double CELL = 1.0;  ///< grid cell, metres (about a table)
	/** Unique for cells within +-2^31 of the origin; beyond, cells may share a key, which
	 *  costs only time (near() is a superset, filtered by distance). */
	static int64_t key(int64_t ix, int64_t iy)
	{
		return static_cast<int64_t>((static_cast<uint64_t>(ix) << 32) ^ static_cast<uint32_t>(iy));
	}
	/** Clamped to +-2^62, so any finite coordinate has a cell and loops over cells end. */
	static int64_t cellOf(double v)
	{
		constexpr double LIM = 4.611686018427387904e18;  // 2^62
		return static_cast<int64_t>(std::clamp(std::floor(v / CELL), -LIM, LIM));
	}
	/** Objects whose centres lie within `radius` of (x, y) (a superset, cell-wise). */
	void near(double x, double y, double radius, std::vector<uint32_t>& out) const;
	void index(uint32_t i);
	void unindex(uint32_t i);

	TOptions m_opts;
	std::vector<TMapObject> m_objects;
	std::unordered_map<int64_t, std::vector<uint32_t>> m_grid;
	double m_reach = 0;  ///< largest centre-to-leg-edge distance of any object
	std::vector<uint32_t> m_near;  // scratch
};
}  // namespace whiskermap::maps
