#include <whiskermap/core/Angles.h>
#include <whiskermap/maps/TableConsolidator.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace whiskermap::maps
{
void TableConsolidator::index(uint32_t i)
{
	const auto& t = m_objects[i].table;
	m_reach = std::max(m_reach, std::hypot(t.length, t.width) / 2 + t.leg_width);
	m_grid[key(cellOf(m_objects[i].table.x), cellOf(m_objects[i].table.y))].push_back(i);
}

void TableConsolidator::unindex(uint32_t i)
{
	auto& cell = m_grid[key(cellOf(m_objects[i].table.x), cellOf(m_objects[i].table.y))];
	cell.erase(std::find(cell.begin(), cell.end(), i));
}

void TableConsolidator::setObjects(std::vector<TMapObject> objects)
{
	m_objects = std::move(objects);
	m_grid.clear();
	m_reach = 0;
	for (uint32_t i = 0; i < m_objects.size(); i++) index(i);
}

void TableConsolidator::near(double x, double y, double radius, std::vector<uint32_t>& out) const
{
	out.clear();
	for (int64_t ix = cellOf(x - radius); ix <= cellOf(x + radius); ix++)
		for (int64_t iy = cellOf(y - radius); iy <= cellOf(y + radius); iy++)
			if (auto it = m_grid.find(key(ix, iy)); it != m_grid.end())
				out.insert(out.end(), it->second.begin(), it->second.end());
	std::sort(out.begin(), out.end());  // deterministic order, whatever the hashing
}

void TableConsolidator::addPose(
	const std::vector<world::Table>& tables, const std::vector<obs::Shapelet>& shapelets)
{
	const uint32_t before = static_cast<uint32_t>(m_objects.size());
	std::vector<uint32_t> matched;
	for (const auto& t : tables)
	{
		// Nearest object within the gates, not already matched by this pose.
		uint32_t best = UINT32_MAX;
		double bestDist = m_opts.merge_distance;
		near(t.x, t.y, m_opts.merge_distance, m_near);
		for (uint32_t i : m_near)
		{
			const auto& o = m_objects[i].table;
			const double d = std::hypot(o.x - t.x, o.y - t.y);
			// the same class and size only (object catalogue; always so without one)
			const bool sameClass = o.object_class == t.object_class && o.length == t.length && o.width == t.width;
			if (i < before && d <= bestDist && sameClass &&
				std::find(matched.begin(), matched.end(), i) == matched.end() &&
				std::abs(core::angleDiff(o.yaw, t.yaw, M_PI)) <= m_opts.merge_angle)
				best = i, bestDist = d;
		}
		if (best == UINT32_MAX)
		{
			best = static_cast<uint32_t>(m_objects.size());
			m_objects.push_back(TMapObject{t});
		}
		else
		{
			matched.push_back(best);
			unindex(best);
		}
		auto& o = m_objects[best];
		o.support++;
		o.evidence++;
		o.sum_x += t.x, o.sum_y += t.y;
		o.sum_cos2 += std::cos(2 * t.yaw), o.sum_sin2 += std::sin(2 * t.yaw);
		o.table.x = o.sum_x / o.support;
		o.table.y = o.sum_y / o.support;
		o.table.yaw = 0.5 * std::atan2(o.sum_sin2, o.sum_cos2);  // circular mean modulo pi
		index(best);
	}
	// Contacts on an object's legs count on it; older objects this pose touched on a leg but
	// did not find count it against them.
	std::vector<uint32_t> touched;
	for (const auto& s : shapelets)
	{
		near(s.x, s.y, m_reach + m_opts.evidence_margin, m_near);
		for (uint32_t i : m_near)
		{
			auto& o = m_objects[i];
			int leg = -1;
			for (int k = 0; k < 4 && leg < 0; k++)
				if (o.table.leg(k, 0).distance({s.x, s.y}) <= m_opts.evidence_margin) leg = k;
			if (leg < 0) continue;
			o.contacts++;
			o.legMask = static_cast<uint8_t>(o.legMask | (1u << leg));
			if (i < before && std::find(matched.begin(), matched.end(), i) == matched.end() &&
				std::find(touched.begin(), touched.end(), i) == touched.end())
				touched.push_back(i);
		}
	}
	for (uint32_t i : touched) m_objects[i].evidence++;
}
}  // namespace whiskermap::maps
