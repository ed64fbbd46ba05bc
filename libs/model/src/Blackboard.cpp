#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Densities.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::model
{
namespace
{
/** Cell of the leg hashes: half a table length, so that the widest query (pair partners, a
 *  table diagonal away) spans a few cells and the narrow ones (overlaps, contacts) one to four. */
double legCell(const ModelParams& p) { return std::max(4 * p.leg_width, p.maxLength() / 2); }
}  // namespace

Blackboard::Blackboard(const ModelParams& p)
	: m_p(p),
	  m_shapelets(std::make_shared<const std::vector<obs::Shapelet>>()),
	  m_tableHash(p.maxDiagonal()),
	  m_legHash(legCell(p)),
	  m_contextTableHash(p.maxDiagonal()),
	  m_contextLegHash(legCell(p))
{
}

void Blackboard::reset(const std::vector<obs::Shapelet>& shapelets)
{
	m_shapelets = std::make_shared<const std::vector<obs::Shapelet>>(shapelets);
	m_shapeletParent.assign(shapelets.size(), NONE);
	m_shapeletWall.assign(shapelets.size(), NONE);
	m_walls.clear();
	m_tables.clear();
	m_legs.clear();
	// Per-id side tables (children, dormancy) keep their storage: add*() resets an id's entries
	// when its slot is used again. The legs' evidence is emptied (its storage kept): a copy of
	// the board copies it whole, and a large earlier board would leave every later copy large.
	m_evidence.clear();
	m_contextTables.clear();
	m_contextLegs.clear();
	m_tableHash.clear();
	m_legHash.clear();
	m_contextTableHash.clear();
	m_contextLegHash.clear();
	m_maxLegRadius = 0;
	m_swept.clear();
}

void Blackboard::reset(const std::vector<obs::Shapelet>& shapelets, const std::vector<obs::SweptSector>& swept)
{
	reset(shapelets);
	m_swept.assign(swept);
}

void Blackboard::grow()
{
	const auto nt = static_cast<size_t>(m_tables.capacity()), nl = static_cast<size_t>(m_legs.capacity());
	if (m_tableLegs.size() < nt) m_tableLegs.resize(nt), m_tableDormant.resize(nt, 0);
	if (m_legShapelets.size() < nl) m_legShapelets.resize(nl), m_legDormant.resize(nl, 0);
	if (m_evidence.size() < nl) m_evidence.resize(nl);
}

void Blackboard::insertSorted(std::vector<Id>& v, Id id) { v.insert(std::upper_bound(v.begin(), v.end(), id), id); }

void Blackboard::eraseValue(std::vector<Id>& v, Id id)
{
	const auto it = std::lower_bound(v.begin(), v.end(), id);
	if (it != v.end() && *it == id) v.erase(it);
}

Id Blackboard::addTable(const Table& t)
{
	const Id id = m_tables.add(t);
	grow();
	m_tableLegs[id].clear();
	m_tableDormant[id] = 0;
	m_tableHash.insert(id, t.x, t.y);
	return id;
}

Id Blackboard::addLeg(const Leg& l, const LegEvidence& evidence)
{
	Leg unlinked = l;
	unlinked.parent = NONE;
	unlinked.corner = -1;
	const Id id = m_legs.add(unlinked);
	grow();
	m_legShapelets[id].clear();
	m_legDormant[id] = 0;
	m_evidence[id] = evidence;
	m_legHash.insert(id, l.x, l.y);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
	setLegParent(id, l.parent);
	return id;
}

void Blackboard::removeTable(Id id)
{
	const std::vector<Id> legs = m_tableLegs[id];
	for (const Id l : legs) setLegParent(l, NONE);
	m_tableHash.erase(id, m_tables[id].x, m_tables[id].y);
	m_tables.remove(id);
}

void Blackboard::removeLeg(Id id)
{
	for (const Id s : m_legShapelets[id]) m_shapeletParent[static_cast<size_t>(s)] = NONE;
	m_legShapelets[id].clear();
	setLegParent(id, NONE);
	m_evidence[id] = {};
	m_legHash.erase(id, m_legs[id].x, m_legs[id].y);
	m_legs.remove(id);
}

void Blackboard::setLegParent(Id leg, Id table)
{
	Leg& l = m_legs[leg];
	if (l.parent != NONE) eraseValue(m_tableLegs[l.parent], leg);
	l.parent = table;
	l.corner = table == NONE ? -1 : logLegGivenTable(l, m_tables[table], m_p).corner;
	if (table != NONE) insertSorted(m_tableLegs[table], leg);
}

void Blackboard::setShapeletParent(size_t shapelet, Id leg)
{
	Id& parent = m_shapeletParent[shapelet];
	if (parent != NONE) eraseValue(m_legShapelets[parent], static_cast<Id>(shapelet));
	parent = leg;
	if (leg != NONE) insertSorted(m_legShapelets[leg], static_cast<Id>(shapelet));
	if (leg != NONE && m_shapeletWall[shapelet] != NONE) setShapeletWall(shapelet, NONE);
}

Id Blackboard::addWall(const Wall& w, const WallEvidence& evidence)
{
	const Id id = m_walls.add(w);
	const auto n = static_cast<size_t>(m_walls.capacity());
	if (m_wallShapelets.size() < n) m_wallShapelets.resize(n), m_wallEvidence.resize(n), m_wallFrames.resize(n);
	m_wallShapelets[id].clear();
	m_wallEvidence[id] = evidence;
	m_wallFrames[static_cast<size_t>(id)] = w.frame();
	return id;
}

void Blackboard::removeWall(Id id)
{
	for (const Id s : m_wallShapelets[id]) m_shapeletWall[static_cast<size_t>(s)] = NONE;
	m_wallShapelets[id].clear();
	m_wallEvidence[id] = {};
	m_walls.remove(id);
}

void Blackboard::setShapeletWall(size_t shapelet, Id wall)
{
	Id& current = m_shapeletWall[shapelet];
	if (current != NONE) eraseValue(m_wallShapelets[current], static_cast<Id>(shapelet));
	current = wall;
	if (wall == NONE) return;
	insertSorted(m_wallShapelets[wall], static_cast<Id>(shapelet));
	if (m_shapeletParent[shapelet] != NONE) setShapeletParent(shapelet, NONE);
}

void Blackboard::setTable(Id id, const Table& t)
{
	m_tableHash.erase(id, m_tables[id].x, m_tables[id].y);
	m_tables[id] = t;
	m_tableHash.insert(id, t.x, t.y);
	for (const Id l : m_tableLegs[id])
		m_legs[l].corner = logLegGivenTable(m_legs[l], t, m_p).corner;
}

void Blackboard::setLeg(Id id, const Leg& l)
{
	Leg& leg = m_legs[id];
	m_legHash.erase(id, leg.x, leg.y);
	const Id parent = leg.parent;
	leg = l;
	leg.parent = parent;
	leg.corner = parent == NONE ? -1 : logLegGivenTable(leg, m_tables[parent], m_p).corner;
	m_legHash.insert(id, l.x, l.y);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
}

void Blackboard::addContextTable(const Table& t)
{
	m_contextTables.push_back(t);
	m_contextTableHash.insert(static_cast<Id>(m_contextTables.size() - 1), t.x, t.y);
}

void Blackboard::addContextLeg(const Leg& l)
{
	m_contextLegs.push_back(l);
	m_contextLegHash.insert(static_cast<Id>(m_contextLegs.size() - 1), l.x, l.y);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
}

CornerCounts Blackboard::cornerCounts(Id table, Id excludeLeg) const
{
	CornerCounts c{0, 0, 0, 0};
	for (const Id l : m_tableLegs[table])
		if (l != excludeLeg) c[m_legs[l].corner]++;
	return c;
}

HypothesisSet Blackboard::compact() const
{
	HypothesisSet out;
	std::vector<Id> tableIndex(m_tables.capacity(), NONE), legIndex(m_legs.capacity(), NONE);
	for (Id t = 0; t < m_tables.capacity(); t++)
		if (m_tables.alive(t))
		{
			tableIndex[t] = static_cast<Id>(out.tables.size());
			out.tables.push_back(m_tables[t]);
		}
	for (Id l = 0; l < m_legs.capacity(); l++)
		if (m_legs.alive(l))
		{
			legIndex[l] = static_cast<Id>(out.legs.size());
			out.legs.push_back(m_legs[l]);
			Leg& copy = out.legs.back();
			if (copy.parent != NONE) copy.parent = tableIndex[copy.parent];
		}
	for (const Id parent : m_shapeletParent)
		out.shapeletParent.push_back(parent == NONE ? NONE : legIndex[parent]);
	return out;
}
}  // namespace whiskermap::model
