#pragma once
#include <whiskermap/model/Factors.h>
#include <whiskermap/model/HypothesisSet.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/SlotVector.h>
#include <whiskermap/model/SpatialHash.h>
#include <whiskermap/obs/Shapelet.h>

#include <vector>

namespace whiskermap::model
{
/** The blackboard (paper section 5): the shapelets of one time step and the hypotheses
 *  currently believed (tables, legs), with stable ids and explicit parent links, plus a
 *  spatial hash per type for "candidates within a radius" and "same-type overlaps".
 *  Links are kept consistent: removing a hypothesis unlinks its children. */
class Blackboard
{
   public:
	explicit Blackboard(const ModelParams& p);

	/** Empties the blackboard and holds `shapelets`, all without parent. Keeps capacity. */
	void reset(const std::vector<obs::Shapelet>& shapelets);

	const ModelParams& params() const { return m_p; }

	Id addTable(const Table& t);
	/** Adds `l` and links it to l.parent (if not NONE), setting its corner. */
	Id addLeg(const Leg& l);
	void removeTable(Id id);  ///< its legs lose their parent
	void removeLeg(Id id);  ///< its shapelets lose their parent
	/** Links a leg to `table` (NONE: unlinks); the corner is the argmin of eq. 6. */
	void setLegParent(Id leg, Id table);
	void setShapeletParent(size_t shapelet, Id leg);
	/** Moves table `id` to the pose (and size, texture) of `t`; its legs' corners are
	 *  re-derived (argmin of eq. 6). */
	void setTable(Id id, const Table& t);
	/** Moves leg `id` to the pose (and size, texture) of `l`; keeps its parent, re-derives
	 *  its corner. */
	void setLeg(Id id, const Leg& l);

	bool hasTable(Id id) const { return m_tables.alive(id); }
	bool hasLeg(Id id) const { return m_legs.alive(id); }
	const Table& table(Id id) const { return m_tables[id]; }
	const Leg& leg(Id id) const { return m_legs[id]; }
	/** Ids are below these bounds; test hasTable()/hasLeg(). */
	Id tableIdBound() const { return m_tables.capacity(); }
	Id legIdBound() const { return m_legs.capacity(); }
	size_t tableCount() const { return m_tables.count(); }
	size_t legCount() const { return m_legs.count(); }

	const std::vector<obs::Shapelet>& shapelets() const { return m_shapelets; }
	Id shapeletParent(size_t i) const { return m_shapeletParent[i]; }

	/** Child legs of `table` per corner, not counting `excludeLeg`. */
	CornerCounts cornerCounts(Id table, Id excludeLeg = NONE) const;

	/** Calls f(id) for every table (leg) whose centre lies within `radius` of (x, y). */
	template <class F>
	void forEachTableNear(double x, double y, double radius, F&& f) const
	{
		near(m_tableHash, m_tables, x, y, radius, f);
	}
	template <class F>
	void forEachLegNear(double x, double y, double radius, F&& f) const
	{
		near(m_legHash, m_legs, x, y, radius, f);
	}
	/** Largest half-diagonal of any leg added since reset(): bounds overlap searches. */
	double maxLegRadius() const { return m_maxLegRadius; }

	/** Live hypotheses and links with ids renumbered densely. */
	HypothesisSet compact() const;

   private:
	template <class H, class F>
	static void near(
		const SpatialHash& hash, const SlotVector<H>& items, double x, double y, double radius,
		F& f)
	{
		hash.forEachNear(x, y, radius, [&](Id id) {
			const H& h = items[id];
			if ((h.x - x) * (h.x - x) + (h.y - y) * (h.y - y) <= radius * radius) f(id);
		});
	}

	ModelParams m_p;
	std::vector<obs::Shapelet> m_shapelets;
	std::vector<Id> m_shapeletParent;
	SlotVector<Table> m_tables;
	SlotVector<Leg> m_legs;
	SpatialHash m_tableHash, m_legHash;
	double m_maxLegRadius = 0;
};
}  // namespace whiskermap::model
