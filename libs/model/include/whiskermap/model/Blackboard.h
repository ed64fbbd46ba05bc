#pragma once
#include <whiskermap/model/Factors.h>
#include <whiskermap/model/HypothesisSet.h>
#include <whiskermap/model/LegEvidence.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/SlotVector.h>
#include <whiskermap/model/SpatialHash.h>
#include <whiskermap/model/SweptGrid.h>
#include <whiskermap/model/SweptSpace.h>
#include <whiskermap/model/Wall.h>
#include <whiskermap/model/WallEvidence.h>
#include <whiskermap/obs/Shapelet.h>

#include <memory>
#include <vector>

namespace whiskermap::model
{
/** The blackboard (paper section 5): the shapelets of one inference problem and the
 *  hypotheses currently believed (tables, legs), with stable ids and explicit parent links,
 *  plus a spatial hash per type for "candidates within a radius" and "same-type overlaps".
 *  Links are kept consistent: removing a hypothesis unlinks its children; each table knows
 *  its legs and each leg its shapelets (ascending), so local scores cost the size of a
 *  Markov blanket, not of the board.
 *
 *  For the lasting map (doc/map-plugin.md) a board is one local problem cut out of the map:
 *  legs may carry folded evidence (LegEvidence: contacts explained earlier), hypotheses may
 *  be dormant (kept, scored and changeable by their neighbours' moves, but not visited by
 *  the sampler), and fixed context objects just outside the problem enter the overlap
 *  factor (eq. 16) only. */
class Blackboard
{
   public:
	explicit Blackboard(const ModelParams& p);

	/** Empties the blackboard and holds `shapelets`, all without parent, and no free space.
	 *  Keeps capacity. */
	void reset(const std::vector<obs::Shapelet>& shapelets);
	/** Same, with the free space the whiskers of the shapelets' sweeps swept (eq. 21). */
	void reset(const std::vector<obs::Shapelet>& shapelets, const std::vector<obs::SweptSector>& swept);

	const ModelParams& params() const { return m_p; }

	Id addTable(const Table& t);
	/** Adds `l` with its folded evidence and links it to l.parent (if not NONE). */
	Id addLeg(const Leg& l, const LegEvidence& evidence = {});
	void removeTable(Id id);  ///< its legs lose their parent
	void removeLeg(Id id);  ///< its shapelets lose their parent; its evidence goes with it
	/** Links a leg to `table` (NONE: unlinks); the corner is the argmin of eq. 6. */
	void setLegParent(Id leg, Id table);
	/** Links shapelet to `leg` (NONE: unlinks it from its leg); a shapelet linked to a leg
	 *  leaves its wall. */
	void setShapeletParent(size_t shapelet, Id leg);
	/** Moves table `id` to the pose (and size, texture) of `t`; its legs' corners are
	 *  re-derived (argmin of eq. 6). */
	void setTable(Id id, const Table& t);
	/** Moves leg `id` to the pose (and size, texture) of `l`; keeps its parent, re-derives
	 *  its corner. */
	void setLeg(Id id, const Leg& l);
	void setEvidence(Id leg, const LegEvidence& e) { m_evidence[leg] = e; }

	bool hasTable(Id id) const { return m_tables.alive(id); }
	bool hasLeg(Id id) const { return m_legs.alive(id); }
	const Table& table(Id id) const { return m_tables[id]; }
	const Leg& leg(Id id) const { return m_legs[id]; }
	const LegEvidence& evidence(Id leg) const { return m_evidence[leg]; }
	/** Child legs of a table, shapelets of a leg: ascending. */
	const std::vector<Id>& legsOf(Id table) const { return m_tableLegs[table]; }
	const std::vector<Id>& shapeletsOf(Id leg) const { return m_legShapelets[leg]; }
	/** True when leg `l` explains data: a shapelet on the board or folded evidence. */
	bool explains(Id l) const { return !m_legShapelets[l].empty() || !m_evidence[l].empty(); }

	/** Dormant hypotheses are not visited by the sampler (doc/sampler.md); new ones never are. */
	void setTableDormant(Id id, bool d) { m_tableDormant[id] = d; }
	void setLegDormant(Id id, bool d) { m_legDormant[id] = d; }
	bool tableDormant(Id id) const { return m_tableDormant[id]; }
	bool legDormant(Id id) const { return m_legDormant[id]; }

	/** Fixed objects around the problem: they count in the overlap factor (eq. 16) of the
	 *  board's hypotheses and nowhere else. */
	void addContextTable(const Table& t);
	void addContextLeg(const Leg& l);
	const std::vector<Table>& contextTables() const { return m_contextTables; }
	const std::vector<Leg>& contextLegs() const { return m_contextLegs; }

	/** Walls (doc/model.md, "Walls"): a shapelet's explicit parent is a leg or a wall, never
	 *  both. A wall may carry folded evidence (the lasting map's). */
	Id addWall(const Wall& w, const WallEvidence& evidence = {});
	void removeWall(Id id);  ///< its shapelets lose their parent
	void setWall(Id id, const Wall& w) { m_walls[id] = w, m_wallFrames[static_cast<size_t>(id)] = w.frame(); }
	/** Links shapelet to `wall` (leaving its leg or other wall); NONE: unlinks it from its wall. */
	void setShapeletWall(size_t shapelet, Id wall);
	bool hasWall(Id id) const { return m_walls.alive(id); }
	const Wall& wall(Id id) const { return m_walls[id]; }
	/** wall(id).frame(), kept as the wall changes. */
	const Wall::Frame& wallFrame(Id id) const { return m_wallFrames[static_cast<size_t>(id)]; }
	const WallEvidence& wallEvidence(Id id) const { return m_wallEvidence[id]; }
	const std::vector<Id>& shapeletsOfWall(Id id) const { return m_wallShapelets[id]; }
	Id shapeletWall(size_t s) const { return m_shapeletWall[s]; }
	/** True when shapelet s has an explicit cause (a leg or a wall). */
	bool explained(size_t s) const { return m_shapeletParent[s] != NONE || m_shapeletWall[s] != NONE; }
	bool wallExplains(Id w) const { return !m_wallShapelets[w].empty() || !m_wallEvidence[w].empty(); }
	Id wallIdBound() const { return m_walls.capacity(); }
	size_t wallCount() const { return m_walls.count(); }

	/** Ids are below these bounds; test hasTable()/hasLeg(). */
	Id tableIdBound() const { return m_tables.capacity(); }
	Id legIdBound() const { return m_legs.capacity(); }
	size_t tableCount() const { return m_tables.count(); }
	size_t legCount() const { return m_legs.count(); }

	const std::vector<obs::Shapelet>& shapelets() const { return *m_shapelets; }
	/** The problem's swept free space (negative evidence, eq. 21); empty unless given. */
	const SweptSpace& swept() const { return m_swept; }
	/** The lasting map's swept grid, whose untouched cells count against walls (eq. 25):
	 *  null (the default) for none. Not owned; reset() keeps it. */
	void setSweptGrid(const SweptGrid* g) { m_grid = g; }
	const SweptGrid* sweptGrid() const { return m_grid; }
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
	/** Same for the context objects (f gets their index in contextTables()/contextLegs()). */
	template <class F>
	void forEachContextTableNear(double x, double y, double radius, F&& f) const
	{
		near(m_contextTableHash, m_contextTables, x, y, radius, f);
	}
	template <class F>
	void forEachContextLegNear(double x, double y, double radius, F&& f) const
	{
		near(m_contextLegHash, m_contextLegs, x, y, radius, f);
	}
	/** Largest half-diagonal of any leg added since reset(): bounds overlap searches. */
	double maxLegRadius() const { return m_maxLegRadius; }

	/** Live hypotheses and links with ids renumbered densely. */
	HypothesisSet compact() const;

   private:
	template <class Items, class F>
	static void near(const SpatialHash& hash, const Items& items, double x, double y, double radius, F& f)
	{
		hash.forEachNear(x, y, radius, [&](Id id) {
			const auto& h = items[id];
			if ((h.x - x) * (h.x - x) + (h.y - y) * (h.y - y) <= radius * radius) f(id);
		});
	}
	static void insertSorted(std::vector<Id>& v, Id id);
	static void eraseValue(std::vector<Id>& v, Id id);
	/** Grows the per-id side tables to the slot vectors' capacity. */
	void grow();

	ModelParams m_p;
	/** Set by reset() only, so copies of the board (a move's backup, the MAP candidate) share it. */
	std::shared_ptr<const std::vector<obs::Shapelet>> m_shapelets;
	std::vector<Id> m_shapeletParent;
	SlotVector<Table> m_tables;
	SlotVector<Leg> m_legs;
	std::vector<LegEvidence> m_evidence;  ///< per leg id
	std::vector<std::vector<Id>> m_tableLegs, m_legShapelets;  ///< children, per id
	std::vector<uint8_t> m_tableDormant, m_legDormant;
	std::vector<Table> m_contextTables;
	std::vector<Leg> m_contextLegs;
	SpatialHash m_tableHash, m_legHash, m_contextTableHash, m_contextLegHash;
	double m_maxLegRadius = 0;
	SweptSpace m_swept;
	const SweptGrid* m_grid = nullptr;
	SlotVector<Wall> m_walls;
	std::vector<WallEvidence> m_wallEvidence;  ///< per wall id
	std::vector<Wall::Frame> m_wallFrames;  ///< per wall id
	std::vector<std::vector<Id>> m_wallShapelets;  ///< per wall id, ascending
	std::vector<Id> m_shapeletWall;  ///< per shapelet: its wall, or NONE
};
}  // namespace whiskermap::model
