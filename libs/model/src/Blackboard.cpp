#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Densities.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::model
{
Blackboard::Blackboard(const ModelParams& p)
	: m_p(p),
	  m_tableHash(std::hypot(p.table_length, p.table_width)),
	  m_legHash(4 * p.leg_width)
{
}

void Blackboard::reset(const std::vector<obs::Shapelet>& shapelets)
{
	m_shapelets.assign(shapelets.begin(), shapelets.end());
	m_shapeletParent.assign(shapelets.size(), NONE);
	m_tables.clear();
	m_legs.clear();
	m_tableHash.clear();
	m_legHash.clear();
	m_maxLegRadius = 0;
}

Id Blackboard::addTable(const Table& t)
{
	const Id id = m_tables.add(t);
	m_tableHash.insert(id, t.x, t.y);
	return id;
}

Id Blackboard::addLeg(const Leg& l)
{
	Leg unlinked = l;
	unlinked.parent = NONE;
	unlinked.corner = -1;
	const Id id = m_legs.add(unlinked);
	m_legHash.insert(id, l.x, l.y);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
	setLegParent(id, l.parent);
	return id;
}

void Blackboard::removeTable(Id id)
{
	for (Id l = 0; l < m_legs.capacity(); l++)
		if (m_legs.alive(l) && m_legs[l].parent == id) setLegParent(l, NONE);
	m_tableHash.erase(id, m_tables[id].x, m_tables[id].y);
	m_tables.remove(id);
}

void Blackboard::removeLeg(Id id)
{
	for (auto& parent : m_shapeletParent)
		if (parent == id) parent = NONE;
	m_legHash.erase(id, m_legs[id].x, m_legs[id].y);
	m_legs.remove(id);
}

void Blackboard::setLegParent(Id leg, Id table)
{
	Leg& l = m_legs[leg];
	l.parent = table;
	l.corner = table == NONE ? -1 : logLegGivenTable(l, m_tables[table], m_p).corner;
}

void Blackboard::setShapeletParent(size_t shapelet, Id leg) { m_shapeletParent[shapelet] = leg; }

void Blackboard::setTable(Id id, const Table& t)
{
	m_tableHash.erase(id, m_tables[id].x, m_tables[id].y);
	m_tables[id] = t;
	m_tableHash.insert(id, t.x, t.y);
	for (Id l = 0; l < m_legs.capacity(); l++)
		if (m_legs.alive(l) && m_legs[l].parent == id) setLegParent(l, id);
}

void Blackboard::setLeg(Id id, const Leg& l)
{
	const Id parent = m_legs[id].parent;
	m_legHash.erase(id, m_legs[id].x, m_legs[id].y);
	m_legs[id] = l;
	m_legHash.insert(id, l.x, l.y);
	m_maxLegRadius = std::max(m_maxLegRadius, std::hypot(l.wx, l.wy) / 2);
	setLegParent(id, parent);
}

CornerCounts Blackboard::cornerCounts(Id table, Id excludeLeg) const
{
	CornerCounts c{0, 0, 0, 0};
	for (Id l = 0; l < m_legs.capacity(); l++)
		if (l != excludeLeg && m_legs.alive(l) && m_legs[l].parent == table) c[m_legs[l].corner]++;
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
