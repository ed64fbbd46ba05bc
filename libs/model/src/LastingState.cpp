#include <whiskermap/model/Densities.h>
#include <whiskermap/model/LastingState.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace whiskermap::model
{
namespace
{
constexpr double GRID_CELL = 0.5;  ///< metres: legs and contacts

double dist2(double ax, double ay, double bx, double by) { return (ax - bx) * (ax - bx) + (ay - by) * (ay - by); }

template <class T>
void growTo(std::vector<T>& v, Id bound, const T& value = T())
{
	if (v.size() < static_cast<size_t>(bound)) v.resize(static_cast<size_t>(bound), value);
}

/** Evidence as the store keeps it: null when empty, else an immutable shared copy. */
std::shared_ptr<const LegEvidence> share(const LegEvidence& e)
{
	return e.empty() ? nullptr : std::make_shared<const LegEvidence>(e);
}
}  // namespace

LastingState::LastingState(const ModelParams& sizes)
	: m_sizes(sizes),
	  m_tableGrid(sizes.maxDiagonal()),
	  m_legGrid(GRID_CELL),
	  m_contactGrid(GRID_CELL)
{
}

void LastingState::clear() { *this = LastingState(m_sizes); }

const LegEvidence& LastingState::evidence(Id l) const
{
	static const LegEvidence none;
	return m_evidence[static_cast<size_t>(l)] ? *m_evidence[static_cast<size_t>(l)] : none;
}

size_t LastingState::legsBeside(double distance) const
{
	size_t n = 0;
	for (Id a = 0; a < legIdBound(); a++)
	{
		if (!hasLeg(a)) continue;
		const Leg& l = leg(a);
		bool beside = false;
		m_legGrid.forEachNear(l.x, l.y, distance, [&](Id b) {
			beside = beside || (b != a && std::hypot(leg(b).x - l.x, leg(b).y - l.y) <= distance);
		});
		n += beside;
	}
	return n;
}

LastingState::Sharing LastingState::sharing() const
{
	Sharing s;
	const auto add = [&s](const auto& chunked) { s.shared += chunked.sharedChunks(), s.chunks += chunked.chunkCount(); };
	add(m_legs.items()), add(m_contacts.items()), add(m_contactLeg), add(m_evidence), add(m_legContacts);
	add(m_tableGrid), add(m_legGrid), add(m_contactGrid);
	return s;
}

Id LastingState::addContact(const obs::Shapelet& s)
{
	return newContact(s, m_seq++);
}

Id LastingState::newContact(const obs::Shapelet& s, uint64_t seq)
{
	const Id c = m_contacts.add(std::make_shared<const Reading>(Reading{s, seq}));
	m_contactLeg.growTo(static_cast<size_t>(m_contacts.capacity()), NONE);
	m_contactLeg.edit(static_cast<size_t>(c)) = NONE;
	m_contactGrid.insert(c, s.x, s.y);
	return c;
}

void LastingState::dropContact(Id c)
{
	if (m_contactLeg[static_cast<size_t>(c)] == NONE) m_contactGrid.erase(c, shapelet(c).x, shapelet(c).y);
	m_contacts.edit(c).reset();  // the reading goes when no copy of the state holds it
	m_contacts.remove(c);
}

Id LastingState::addTable(const Table& t, double existence)
{
	const Id id = m_tables.add(t);
	growTo(m_existence, m_tables.capacity(), 0.0);
	growTo(m_reported, m_tables.capacity());
	growTo(m_chainSpread, m_tables.capacity());
	growTo(m_tableLegs, m_tables.capacity());
	m_existence[id] = existence;
	m_reported[id] = t;
	m_chainSpread[id] = {};
	m_tableLegs[id].clear();
	m_tableGrid.insert(id, t.x, t.y);
	return id;
}

Id LastingState::addLeg(const Leg& l, std::shared_ptr<const LegEvidence> e)
{
	const Id id = m_legs.add(l);
	m_evidence.growTo(static_cast<size_t>(m_legs.capacity()));
	m_legContacts.growTo(static_cast<size_t>(m_legs.capacity()));
	m_evidence.edit(id) = std::move(e);
	if (!m_legContacts[id].empty()) m_legContacts.edit(id).clear();
	m_legGrid.insert(id, l.x, l.y);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
	if (l.parent != NONE) m_tableLegs[l.parent].push_back(id);
	return id;
}

Id LastingState::setLeg(Id id, const Leg& l, const LegEvidence& e)
{
	const Leg& was = leg(id);
	m_legGrid.move(id, was.x, was.y, l.x, l.y);
	if (!(was == l)) m_legs.edit(id) = l;
	if (!(evidence(id) == e)) m_evidence.edit(id) = share(e);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
	if (l.parent != NONE) m_tableLegs[l.parent].push_back(id);
	return id;
}

size_t LastingState::mergeOverlappingLegs(
	const std::vector<Id>& legs, std::vector<Id>& kept, std::vector<Id>& touched, double gap)
{
	size_t merges = 0;
	std::vector<Id> near;
	for (const Id start : legs)
	{
		Id a = start;
		while (a != NONE && hasLeg(a))
		{
			OrientedRect r = legRect(leg(a));
			r.hx += gap, r.hy += gap;
			near.clear();
			m_legGrid.forEachNear(r.cx, r.cy, std::hypot(r.hx, r.hy) + m_maxLegRadius, [&](Id o) {
				if (o != a && r.overlaps(legRect(leg(o)))) near.push_back(o);
			});
			if (near.empty()) break;
			// By content, never by store id (a reloaded state numbers its legs differently).
			const auto before = [&](Id p, Id q) {
				return std::make_tuple(contactsExplained(q), leg(p).x, leg(p).y) <
					   std::make_tuple(contactsExplained(p), leg(q).x, leg(q).y);
			};  // more contacts first, then by position
			const Id b = *std::min_element(near.begin(), near.end(), before);
			const bool keepA = before(a, b);
			const Id into = keepA ? a : b, from = keepA ? b : a;
			const std::vector<Id> contacts = m_legContacts[from];  // relinked first: never unexplained
			for (const Id c : contacts) setContactLeg(c, into);
			LegEvidence merged = evidence(into);
			merged.merge(evidence(from));
			m_evidence.edit(into) = share(merged);
			const Id parent = leg(from).parent;
			removeLeg(from);
			if (parent != NONE)
			{
				touched.push_back(parent);
				if (m_tableLegs[parent].empty()) removeTable(parent);
			}
			kept.push_back(into);
			merges++;
			a = into;  // it may overlap a third
		}
	}
	return merges;
}

void LastingState::removeTable(Id t)
{
	for (const Id l : m_tableLegs[t])
	{
		Leg& orphan = m_legs.edit(l);
		orphan.parent = NONE, orphan.corner = -1;
	}
	m_tableLegs[t].clear();
	m_tableGrid.erase(t, m_tables[t].x, m_tables[t].y);
	m_tables.remove(t);
}

void LastingState::removeLeg(Id l)
{
	const std::vector<Id> contacts = m_legContacts[l];
	for (const Id c : contacts) setContactLeg(c, NONE);
	const Id parent = leg(l).parent;
	if (parent != NONE)
	{
		auto& v = m_tableLegs[parent];
		v.erase(std::remove(v.begin(), v.end(), l), v.end());
	}
	if (m_evidence[l]) m_evidence.edit(l).reset();
	m_legGrid.erase(l, leg(l).x, leg(l).y);
	m_legs.remove(l);
}

void LastingState::setContactLeg(Id c, Id l)
{
	if (m_contactLeg[static_cast<size_t>(c)] == l) return;
	Id& leg = m_contactLeg.edit(static_cast<size_t>(c));
	const obs::Shapelet& k = shapelet(c);
	if (leg == NONE)
		m_contactGrid.erase(c, k.x, k.y);
	else
	{
		auto& v = m_legContacts.edit(leg);
		v.erase(std::remove(v.begin(), v.end(), c), v.end());
	}
	leg = l;
	if (l == NONE)
		m_contactGrid.insert(c, k.x, k.y);
	else
		m_legContacts.edit(l).push_back(c);
}

void LastingState::extract(const std::vector<Id>& around, const Radii& radii, const ModelParams& model, Region& out) const
{
	if (!(out.board.params() == model)) out.board = Blackboard(model);
	if (++out.epoch == 0)  // wrapped: marks of 2^32 extractions ago would look fresh
	{
		for (auto* marks : {&out.tableMark, &out.legMark, &out.contactMark}) std::fill(marks->begin(), marks->end(), 0u);
		out.epoch = 1;
	}
	growTo(out.tableMark, m_tables.capacity(), 0u);
	growTo(out.legMark, m_legs.capacity(), 0u);
	growTo(out.contactMark, m_contacts.capacity(), 0u);
	const auto mark = [&out](std::vector<uint32_t>& marks, Id id) {  // false when already marked this extraction
		if (marks[static_cast<size_t>(id)] == out.epoch) return false;
		marks[static_cast<size_t>(id)] = out.epoch;
		return true;
	};
	out.tables.clear(), out.legs.clear(), out.contacts.clear();
	std::vector<Id> visitLegs, visitTables, contextTables, contextLegs;
	const double halfDiagonal = model.maxDiagonal() / 2;
	for (const Id a : around)
	{
		const double x = shapelet(a).x, y = shapelet(a).y;
		m_legGrid.forEachNear(x, y, radii.board, [&](Id l) {
			const Leg& leg = m_legs[l];
			const double d2 = dist2(leg.x, leg.y, x, y);
			if (d2 > radii.board * radii.board) return;
			if (mark(out.legMark, l)) out.legs.push_back(l);
			if (d2 <= radii.visit * radii.visit) visitLegs.push_back(l);
		});
		// Tables with a corner near the contact: it may be one of their (invented) legs.
		m_tableGrid.forEachNear(x, y, radii.visit + halfDiagonal, [&](Id t) {
			for (int c = 0; c < 4; c++)
			{
				double cx = 0, cy = 0;
				tableCorner(m_tables[t], c, model, cx, cy);
				if (dist2(cx, cy, x, y) <= radii.visit * radii.visit)
				{
					visitTables.push_back(t);
					if (mark(out.tableMark, t)) out.tables.push_back(t);
					return;
				}
			}
		});
		m_contactGrid.forEachNear(x, y, radii.board, [&](Id c) {
			if (dist2(shapelet(c).x, shapelet(c).y, x, y) <= radii.board * radii.board &&
				mark(out.contactMark, c))
				out.contacts.push_back(c);
		});
	}
	// Closure: the tables of the board's legs, then every leg of the board's tables.
	for (size_t i = 0, n = out.legs.size(); i < n; i++)
	{
		const Id p = m_legs[out.legs[i]].parent;
		if (p != NONE && mark(out.tableMark, p)) out.tables.push_back(p);
	}
	for (const Id l : visitLegs)
		if (m_legs[l].parent != NONE) visitTables.push_back(m_legs[l].parent);
	for (const Id t : out.tables)
		for (const Id l : m_tableLegs[t])
			if (mark(out.legMark, l)) out.legs.push_back(l);
	for (const Id l : out.legs)
		for (const Id c : m_legContacts[l])
			if (mark(out.contactMark, c)) out.contacts.push_back(c);
	// Fixed context: what could overlap the board's hypotheses.
	for (const Id a : around)
	{
		const double x = shapelet(a).x, y = shapelet(a).y;
		m_tableGrid.forEachNear(x, y, radii.context, [&](Id t) {
			if (dist2(m_tables[t].x, m_tables[t].y, x, y) <= radii.context * radii.context && mark(out.tableMark, t))
				contextTables.push_back(t);
		});
		m_legGrid.forEachNear(x, y, radii.context, [&](Id l) {
			if (dist2(m_legs[l].x, m_legs[l].y, x, y) <= radii.context * radii.context && mark(out.legMark, l))
				contextLegs.push_back(l);
		});
	}
	// Board order from the content alone (positions; contacts by age), never from store ids:
	// a copied or reloaded state then continues exactly as the original.
	const auto byPose = [](const auto& items) {
		return [&items](Id a, Id b) {
			const auto &p = items[a], &q = items[b];
			return p.x != q.x ? p.x < q.x : p.y != q.y ? p.y < q.y : p.theta < q.theta;
		};
	};
	std::sort(out.tables.begin(), out.tables.end(), byPose(m_tables));
	std::sort(out.legs.begin(), out.legs.end(), byPose(m_legs));
	std::sort(out.contacts.begin(), out.contacts.end(), [&](Id a, Id b) { return m_contacts[a]->seq < m_contacts[b]->seq; });
	std::sort(contextTables.begin(), contextTables.end(), byPose(m_tables));
	std::sort(contextLegs.begin(), contextLegs.end(), byPose(m_legs));
	// Walls whose slab comes within the board radius of a new contact (in store order).
	out.walls.clear();
	for (size_t w = 0; w < m_walls.size(); w++)
	{
		const OrientedRect r = m_walls[w].wall.rect();
		for (const Id a : around)
			if (r.perimeter(shapelet(a).x, shapelet(a).y).distance <= radii.board)
			{
				out.walls.push_back(w);
				break;
			}
	}

	// The board; out.tableBoard and out.legBoard map store ids to board ids for this extraction.
	std::vector<obs::Shapelet> shapelets;
	shapelets.reserve(out.contacts.size());
	for (const Id c : out.contacts) shapelets.push_back(shapelet(c));
	Blackboard& bb = out.board;
	bb.reset(shapelets);
	growTo(out.tableBoard, m_tables.capacity(), NONE);
	growTo(out.legBoard, m_legs.capacity(), NONE);
	for (const Id t : out.tables) out.tableBoard[static_cast<size_t>(t)] = bb.addTable(m_tables[t]);
	for (const Id l : out.legs)
	{
		Leg leg = m_legs[l];
		leg.parent = leg.parent == NONE ? NONE : out.tableBoard[static_cast<size_t>(leg.parent)];
		out.legBoard[static_cast<size_t>(l)] = bb.addLeg(leg, evidence(l));
	}
	for (size_t i = 0; i < out.contacts.size(); i++)
	{
		const Id l = m_contactLeg[out.contacts[i]];
		if (l != NONE) bb.setShapeletParent(i, out.legBoard[static_cast<size_t>(l)]);
	}
	for (const size_t w : out.walls) bb.addWall(m_walls[w].wall, m_walls[w].evidence);
	// Dormant: everything but the visited legs and tables.
	for (size_t i = 0; i < out.tables.size(); i++) bb.setTableDormant(static_cast<Id>(i), true);
	for (size_t i = 0; i < out.legs.size(); i++) bb.setLegDormant(static_cast<Id>(i), true);
	for (const Id t : visitTables) bb.setTableDormant(out.tableBoard[static_cast<size_t>(t)], false);
	for (const Id l : visitLegs) bb.setLegDormant(out.legBoard[static_cast<size_t>(l)], false);
	for (const Id t : contextTables) bb.addContextTable(m_tables[t]);
	for (const Id l : contextLegs) bb.addContextLeg(m_legs[l]);
}

void LastingState::replace(
	const Region& r, const Blackboard& solved, const std::vector<double>& existence, std::vector<Id>& newTables,
	std::vector<Id>& newLegs, const std::vector<double>& wallExistence, const ModelParams& model)
{
	// The region's walls, by descending index (erasing keeps the lower indices).
	std::vector<size_t> gone = r.walls;
	std::sort(gone.rbegin(), gone.rend());
	for (const size_t w : gone) m_walls.erase(m_walls.begin() + static_cast<std::ptrdiff_t>(w));
	std::vector<size_t> wallIndex(static_cast<size_t>(solved.wallIdBound()), 0);
	for (Id w = 0; w < solved.wallIdBound(); w++)
	{
		if (!solved.hasWall(w)) continue;
		wallIndex[static_cast<size_t>(w)] = m_walls.size();
		m_walls.push_back({solved.wall(w), solved.wallEvidence(w), wallExistence.at(static_cast<size_t>(w))});
	}
	// The region's legs the solution kept keep their store ids, so that a copy of the state
	// shares their chunks while they come back unchanged; the others go. The region's
	// tables hold only region legs (extract()'s closure): they go and come back.
	for (size_t i = 0; i < r.legs.size(); i++)
		if (!solved.hasLeg(static_cast<Id>(i))) removeLeg(r.legs[i]);
	for (const Id t : r.tables) m_tableLegs[t].clear(), removeTable(t);
	newTables.assign(static_cast<size_t>(solved.tableIdBound()), NONE);
	newLegs.assign(static_cast<size_t>(solved.legIdBound()), NONE);
	for (Id t = 0; t < solved.tableIdBound(); t++)
		if (solved.hasTable(t)) newTables[t] = addTable(solved.table(t), existence[t]);
	for (Id l = 0; l < solved.legIdBound(); l++)
	{
		if (!solved.hasLeg(l)) continue;
		Leg leg = solved.leg(l);
		if (leg.parent != NONE) leg.parent = newTables[leg.parent];
		newLegs[l] = static_cast<size_t>(l) < r.legs.size() ? setLeg(r.legs[static_cast<size_t>(l)], leg, solved.evidence(l))
															 : addLeg(leg, share(solved.evidence(l)));
	}
	for (size_t i = 0; i < r.contacts.size(); i++)
	{
		const Id l = solved.shapeletParent(i), w = solved.shapeletWall(i);
		setContactLeg(r.contacts[i], l == NONE ? NONE : newLegs[l]);
		if (w == NONE) continue;
		// A contact a wall explains is folded into the wall's evidence and leaves the store.
		StoredWall& sw = m_walls[wallIndex[static_cast<size_t>(w)]];
		sw.evidence.add(shapelet(r.contacts[i]), sw.wall, solved.wallFrame(w), model);
		dropContact(r.contacts[i]);
	}
	// A kept leg's contacts in insertion order, as a leg built from scratch lists them.
	const auto older = [this](Id a, Id b) { return seq(a) < seq(b); };
	for (size_t i = 0; i < r.legs.size(); i++)
	{
		const Id l = newLegs[i];
		if (l == NONE || std::is_sorted(m_legContacts[l].begin(), m_legContacts[l].end(), older)) continue;
		auto& contacts = m_legContacts.edit(l);
		std::sort(contacts.begin(), contacts.end(), older);
	}
}

void LastingState::fold(Id l, size_t keep, const ModelParams& model)
{
	if (m_legContacts[l].size() <= keep) return;
	auto& contacts = m_legContacts.edit(l);
	LegEvidence folded = evidence(l);  // this copy's own from now on
	while (contacts.size() > keep)
	{
		const auto oldest = std::min_element(contacts.begin(), contacts.end(), [&](Id a, Id b) {
			return seq(a) < seq(b);
		});
		const Id c = *oldest;
		folded.add(shapelet(c), leg(l), model);
		contacts.erase(oldest);
		dropContact(c);
	}
	m_evidence.edit(l) = share(folded);
}

size_t LastingState::forgetUnexplained(Id c, size_t keep, double radius)
{
	const obs::Shapelet s = shapelet(c);
	std::vector<Id> near;
	m_contactGrid.forEachNear(s.x, s.y, radius, [&](Id o) {
		if (dist2(shapelet(o).x, shapelet(o).y, s.x, s.y) <= radius * radius) near.push_back(o);
	});
	if (near.size() <= keep) return 0;
	std::sort(near.begin(), near.end(), [&](Id a, Id b) { return seq(a) < seq(b); });
	const size_t forget = near.size() - keep;
	for (size_t i = 0; i < forget; i++) dropContact(near[i]);
	return forget;
}

void LastingState::restore(
	const std::vector<Table>& tables, const std::vector<double>& existence, const std::vector<Table>& reported,
	const std::vector<Leg>& legs, const std::vector<LegEvidence>& evidence, const std::vector<Contact>& contacts,
	uint64_t seq, const ModelParams& model)
{
	clear();
	std::vector<Id> tableIds, legIds;
	for (size_t i = 0; i < tables.size(); i++)
	{
		tableIds.push_back(addTable(tables[i], existence[i]));
		if (reported.empty()) continue;
		Table& r = m_reported[tableIds.back()];  // the reported pose; class and size are the table's
		r.x = reported.at(i).x, r.y = reported.at(i).y, r.theta = reported.at(i).theta;
	}
	for (size_t i = 0; i < legs.size(); i++)
	{
		Leg l = legs[i];
		l.corner = -1;
		if (l.parent != NONE)
		{
			l.parent = tableIds.at(static_cast<size_t>(l.parent));
			l.corner = logLegGivenTable(l, m_tables[l.parent], model).corner;  // argmin of eq. 6
		}
		legIds.push_back(addLeg(l, share(evidence[i])));
	}
	for (const Contact& k : contacts)
	{
		const Id c = newContact(k.shapelet, k.seq);
		if (k.leg != NONE) setContactLeg(c, legIds.at(static_cast<size_t>(k.leg)));
	}
	m_seq = seq;
}
}  // namespace whiskermap::model
