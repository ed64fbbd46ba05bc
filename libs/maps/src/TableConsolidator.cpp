#include <whiskermap/core/Angles.h>
#include <whiskermap/maps/TableConsolidator.h>

#include <array>
#include <cmath>

namespace whiskermap::maps
{
void TableConsolidator::addPose(
	const std::vector<world::Table>& tables, const std::vector<obs::Shapelet>& shapelets)
{
	const size_t before = m_objects.size();
	std::vector<bool> matched(before, false);
	for (const auto& t : tables)
	{
		// Nearest object within the gates not already matched by this pose.
		size_t best = m_objects.size();
		double bestDist = m_opts.merge_distance;
		for (size_t i = 0; i < before; i++)
		{
			const auto& o = m_objects[i].table;
			const double d = std::hypot(o.x - t.x, o.y - t.y);
			if (!matched[i] && d <= bestDist &&
				std::abs(core::angleDiff(o.yaw, t.yaw, M_PI)) <= m_opts.merge_angle)
				best = i, bestDist = d;
		}
		if (best == m_objects.size()) m_objects.push_back(TMapObject{t});
		else matched[best] = true;
		auto& o = m_objects[best];
		o.support++;
		o.evidence++;
		o.sum_x += t.x, o.sum_y += t.y;
		o.sum_cos2 += std::cos(2 * t.yaw), o.sum_sin2 += std::sin(2 * t.yaw);
		o.table.x = o.sum_x / o.support;
		o.table.y = o.sum_y / o.support;
		o.table.yaw = 0.5 * std::atan2(o.sum_sin2, o.sum_cos2);  // circular mean modulo pi
	}
	// Poses that touched an older object but did not find it count against it.
	for (size_t i = 0; i < before; i++)
	{
		if (matched[i]) continue;
		const auto& t = m_objects[i].table;
		const std::array<world::Obstacle, 4> legs{t.leg(0, 0), t.leg(1, 0), t.leg(2, 0), t.leg(3, 0)};
		bool touched = false;
		for (const auto& s : shapelets)
			for (const auto& l : legs) touched = touched || l.distance({s.x, s.y}) <= m_opts.evidence_margin;
		m_objects[i].evidence += touched;
	}
}
}  // namespace whiskermap::maps
