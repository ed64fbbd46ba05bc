#pragma once
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/CowVector.h>
#include <whiskermap/model/LegEvidence.h>
#include <whiskermap/model/SlotVector.h>
#include <whiskermap/model/SpatialGrid.h>
#include <whiskermap/obs/Shapelet.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace whiskermap::model
{
/** The lasting map's hierarchical state (doc/map-plugin.md, "The lasting map"): every table
 *  and leg it believes, each leg with the evidence of all the contacts it ever explained
 *  (the recent ones as explicit contacts, older ones folded into LegEvidence), and the recent
 *  contacts nothing explains. Memory grows with the objects, not with the contacts: a leg
 *  keeps a bounded number of explicit contacts, and unexplained contacts are bounded per
 *  small cell of space.
 *
 *  Inference edits it locally: extract() cuts the problem around new contacts out as a
 *  Blackboard (hypotheses near them visited, those further out dormant, fixed context
 *  around), the sampler anneals that board, and replace() writes the result back. Nothing far
 *  from the new contacts is read or written: an insertion costs the local density of the
 *  map, never its size. */
class LastingState
{
   public:
	/** A contact kept explicitly: data of the next local problems around it (contact()'s
	 *  view; the store shares the reading and its insertion number between copies). */
	struct Contact
	{
		obs::Shapelet shapelet;
		Id leg = NONE;  ///< explaining leg, or NONE
		uint64_t seq = 0;  ///< insertion order (older contacts fold first)
	};
	/** Radii (metres) of a local problem around new contacts. */
	struct Radii
	{
		double visit = 0;  ///< legs (and tables with a corner) this close are visited
		double board = 0;  ///< legs this close are on the board (partners, adoptees), dormant
		double context = 0;  ///< tables and legs this close stand around as fixed context
	};
	/** A wall of the map (doc/model.md, "Walls"): its pose, the contacts it explained folded
	 *  into constant-memory statistics (it keeps no explicit contacts), its existence. */
	struct StoredWall
	{
		Wall wall;
		WallEvidence evidence;
		double existence = 0;
	};
	/** A table's pose spread from a posterior chain (issue 10; inference::PosteriorChain):
	 *  standard deviations of its centre (metres) and yaw (radians). sd_x < 0: none (the map
	 *  then reports inference::rigidPoseSpread's). */
	struct ChainSpread
	{
		double sd_x = -1, sd_y = -1, sd_yaw = -1;
		bool known() const { return sd_x >= 0; }
	};
	/** A local problem: the board and, per board id, the store id it came from (NONE: new). */
	struct Region
	{
		explicit Region(const ModelParams& p) : board(p) {}
		Blackboard board;
		std::vector<Id> tables, legs, contacts;  ///< store ids of the board's tables, legs, shapelets
		std::vector<size_t> walls;  ///< indices into walls() of the board's walls (board ids 0..)
		/** extract()'s scratch, for any state: epoch marks (a fresh set per extraction,
		 *  cleared in O(1)) and store id -> board id of the last extraction. */
		uint32_t epoch = 0;
		std::vector<uint32_t> tableMark, legMark, contactMark;
		std::vector<Id> tableBoard, legBoard;
	};

	explicit LastingState(const ModelParams& sizes = {});

	/** Adds a contact nothing explains yet; returns its id. */
	Id addContact(const obs::Shapelet& s);

	/** Fills `out` with the local problem around the contacts `around` (store ids), scored
	 *  with `model`. Board order depends on the content only (tables and legs by position,
	 *  contacts by age), not on store ids: equal states, however built (a copy, a reload),
	 *  give equal boards. */
	void extract(const std::vector<Id>& around, const Radii& radii, const ModelParams& model, Region& out) const;

	/** Replaces the region's tables and legs by the live hypotheses of `solved` (a board
	 *  grown from r.board: its first r.tables.size() table ids and r.legs.size() leg ids are
	 *  the region's, later ids new), relinks the region's contacts, and stores
	 *  `existence[t]` for each live table t of `solved`. A region leg that `solved` keeps
	 *  keeps its store id and is written only where it changed (copies of the state go on
	 *  sharing its chunks); the region's tables are removed and added again. Returns the store ids of the
	 *  legs and tables in `newLegs` / `newTables` (board id -> store id, NONE if dead).
	 *  The region's walls are replaced by the live walls of `solved` with `wallExistence[w]`;
	 *  the contacts a wall explains are folded into its evidence at once (scored with `model`)
	 *  and leave the store. */
	void replace(
		const Region& r, const Blackboard& solved, const std::vector<double>& existence, std::vector<Id>& newTables,
		std::vector<Id>& newLegs, const std::vector<double>& wallExistence = {}, const ModelParams& model = {});

	const std::vector<StoredWall>& walls() const { return m_walls; }
	/** Adds walls (deserialization, after restore()). */
	void restoreWalls(const std::vector<StoredWall>& walls) { m_walls.insert(m_walls.end(), walls.begin(), walls.end()); }

	/** Folds the oldest explicit contacts of leg `l` into its evidence (scored with `model`)
	 *  until at most `keep` remain. */
	void fold(Id l, size_t keep, const ModelParams& model);
	/** Eq. 16 made hard in the stored map (doc/map-plugin.md, "No two legs in one place"): each
	 *  live leg of `legs` (store ids; NONE skipped) whose rectangle overlaps another stored
	 *  leg's, or comes within `gap` (m) of it (the rectangle grown by `gap` on every side), is
	 *  merged with it into the one explaining more contacts (a tie: the one with the
	 *  smaller x, then y; several overlapping: the first of them in that order). The
	 *  other's explicit contacts are relinked to it, its evidence is merged into it and it is
	 *  removed; a table left without legs is removed too. Appends the survivor of each merge to
	 *  `kept` and the parent tables that lost a leg to `touched`; returns the merges made. */
	size_t mergeOverlappingLegs(
		const std::vector<Id>& legs, std::vector<Id>& kept, std::vector<Id>& touched, double gap = 0);
	/** Forgets the oldest unexplained contacts in the cell of contact `c` (cells of
	 *  `cellSize`) beyond `keep`; returns how many were forgotten. */
	size_t forgetUnexplained(Id c, size_t keep, double cellSize);

	// Read access.
	Id tableIdBound() const { return m_tables.capacity(); }
	Id legIdBound() const { return m_legs.capacity(); }
	Id contactIdBound() const { return m_contacts.capacity(); }
	bool hasTable(Id t) const { return m_tables.alive(t); }
	bool hasLeg(Id l) const { return m_legs.alive(l); }
	bool hasContact(Id c) const { return m_contacts.alive(c); }
	const Table& table(Id t) const { return m_tables[t]; }
	double existence(Id t) const { return m_existence[t]; }
	/** The pose the map reports for table t (doc/map-plugin.md, "Reported pose"): its rigid
	 *  fit once setReported() was called, else the table itself. */
	const Table& reported(Id t) const { return m_reported[t]; }
	void setReported(Id t, const Table& pose) { m_reported[t] = pose; }
	/** Table t's pose spread from the last posterior chain that scored it (none: not scored by one). */
	const ChainSpread& chainSpread(Id t) const { return m_chainSpread[t]; }
	void setChainSpread(Id t, const ChainSpread& s) { m_chainSpread[t] = s; }
	const Leg& leg(Id l) const { return m_legs[l]; }
	/** Leg l's folded evidence (empty when it folded none). */
	const LegEvidence& evidence(Id l) const;
	/** Contact c's reading: one object for every copy of the state that holds the contact. */
	const obs::Shapelet& shapelet(Id c) const { return m_contacts[c]->shapelet; }
	Contact contact(Id c) const { return {m_contacts[c]->shapelet, m_contactLeg[static_cast<size_t>(c)], m_contacts[c]->seq}; }
	uint64_t seq(Id c) const { return m_contacts[c]->seq; }  ///< contact c's insertion number
	const std::vector<Id>& legsOf(Id t) const { return m_tableLegs[t]; }
	const std::vector<Id>& contactsOf(Id l) const { return m_legContacts[l]; }
	size_t tableCount() const { return m_tables.count(); }
	size_t legCount() const { return m_legs.count(); }
	size_t contactCount() const { return m_contacts.count(); }
	/** Contacts explained by leg l: explicit plus folded. */
	uint64_t contactsExplained(Id l) const { return m_legContacts[l].size() + evidence(l).count(); }
	/** Legs with another leg's centre within `distance` of their own: a solid mapped twice, a
	 *  few centimetres off (doc/slam.md, "Legs mapped again beside the first"), or two objects
	 *  standing that close. */
	size_t legsBeside(double distance) const;
	uint64_t nextSeq() const { return m_seq; }
	/** Chunks of the per-leg and per-contact arrays and of the grids that this state shares
	 *  with its copies, and all of them (doc/map-plugin.md, "Copies"). */
	struct Sharing
	{
		size_t shared = 0, chunks = 0;
	};
	Sharing sharing() const;

	/** Rebuilds a state from its parts (deserialization): tables with their existence and
	 *  reported poses (empty: the tables), legs (parent = index into `tables`) with evidence,
	 *  contacts (leg = index into `legs`); `model` gives the tables' sizes (their classes). */
	void restore(
		const std::vector<Table>& tables, const std::vector<double>& existence, const std::vector<Table>& reported,
		const std::vector<Leg>& legs, const std::vector<LegEvidence>& evidence, const std::vector<Contact>& contacts,
		uint64_t seq, const ModelParams& model);
	void clear();

   private:
	Id addTable(const Table& t, double existence);
	Id addLeg(const Leg& l, std::shared_ptr<const LegEvidence> e);  ///< links to l.parent (a store id)
	/** Leg `id` becomes `l` with evidence `e`, writing only what changed; links to l.parent
	 *  (a store id; the old parent's list is the caller's). Returns `id`. */
	Id setLeg(Id id, const Leg& l, const LegEvidence& e);
	void removeTable(Id t);  ///< after its legs are gone or relinked
	void removeLeg(Id l);  ///< its contacts become unexplained
	void setContactLeg(Id c, Id l);
	Id newContact(const obs::Shapelet& s, uint64_t seq);  ///< unexplained (in the contact grid)
	void dropContact(Id c);  ///< out of the contact grid if unexplained; an explained one must have left its leg's list

	ModelParams m_sizes;  ///< table and leg sizes: search radii, cell sizes
	SlotVector<Table> m_tables;
	/** Per-leg and per-contact arrays are CowVectors: copies of the state (a particle filter's
	 *  resampled maps) share the chunks neither has written since (doc/map-plugin.md, "Copies"). */
	SlotVector<Leg, CowVector<Leg>> m_legs;
	/** A contact's reading and insertion number: immutable, shared by the copies of the state
	 *  that hold the contact (doc/map-plugin.md, "Copies"). */
	struct Reading
	{
		obs::Shapelet shapelet;
		uint64_t seq = 0;
	};
	SlotVector<std::shared_ptr<const Reading>, CowVector<std::shared_ptr<const Reading>>> m_contacts;  ///< null in free slots
	CowVector<Id> m_contactLeg;  ///< per contact, its explaining leg (NONE: none)
	std::vector<double> m_existence;
	std::vector<Table> m_reported;
	std::vector<ChainSpread> m_chainSpread;
	/** Per leg, its folded evidence: null when empty, else immutable and shared by the copies
	 *  of the state (a particle filter's resampled maps) until one of them folds into it,
	 *  which gives that copy its own (doc/map-plugin.md, "Copies"). */
	CowVector<std::shared_ptr<const LegEvidence>> m_evidence;
	std::vector<std::vector<Id>> m_tableLegs;
	CowVector<std::vector<Id>> m_legContacts;
	SpatialGrid m_tableGrid, m_legGrid, m_contactGrid;  ///< contacts: the unexplained ones
	double m_maxLegRadius = 0;  ///< the largest half-diagonal of a leg ever added
	uint64_t m_seq = 0;
	std::vector<StoredWall> m_walls;  ///< few per map: scanned linearly
};
}  // namespace whiskermap::model
