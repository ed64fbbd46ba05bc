#pragma once
#include <whiskermap/model/Blackboard.h>

#include <vector>

namespace whiskermap::inference::moves
{
/** A finite set of candidate poses (doc/sampler.md, "Random scan on a pose grid"): the
 *  discretised pose space of the exact stationary-distribution test. Births on the grid put
 *  a new leg (table) exactly at one of these poses; nothing refits them. */
struct PoseGrid
{
	std::vector<model::Leg> legs;  ///< pose, size and texture; parent is ignored
	std::vector<model::Table> tables;
	size_t maxTables = 1;  ///< table births stop at this many tables (a finite space)

	/** Index of the grid leg with exactly `l`'s pose (x, y, yaw), or -1. */
	int legIndex(const model::Leg& l) const
	{
		for (size_t i = 0; i < legs.size(); i++)
			if (legs[i].x == l.x && legs[i].y == l.y && legs[i].theta == l.theta) return static_cast<int>(i);
		return -1;
	}
	/** Same for tables. */
	int tableIndex(const model::Table& t) const
	{
		for (size_t i = 0; i < tables.size(); i++)
			if (tables[i].x == t.x && tables[i].y == t.y && tables[i].theta == t.theta) return static_cast<int>(i);
		return -1;
	}
};

/** The k-th live leg (table) of `bb` by id, k < legCount() (tableCount()): the random scan's
 *  uniform choice of a hypothesis. */
inline model::Id nthLeg(const model::Blackboard& bb, size_t k)
{
	model::Id id = 0;
	while (!bb.hasLeg(id) || k-- > 0) id++;
	return id;
}
inline model::Id nthTable(const model::Blackboard& bb, size_t k)
{
	model::Id id = 0;
	while (!bb.hasTable(id) || k-- > 0) id++;
	return id;
}
}  // namespace whiskermap::inference::moves
