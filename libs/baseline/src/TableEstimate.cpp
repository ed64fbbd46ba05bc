#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/baseline/TableEstimate.h>
#include <whiskermap/world/Obstacle.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace whiskermap::baseline
{
int TableEstimate::legCount() const
{
	return int(std::count_if(legs.begin(), legs.end(), [](int l) { return l >= 0; }));
}

Eigen::Vector2d TableEstimate::offset(int k, const TBaselineParams& p)
{
	const double sx = (k == 0 || k == 3) ? 1 : -1, sy = k < 2 ? 1 : -1;
	return {sx * p.table_length / 2, sy * p.table_width / 2};
}

Eigen::Vector2d TableEstimate::corner(int k, const TBaselineParams& p) const
{
	return centre + Eigen::Rotation2Dd(yaw) * offset(k, p);
}

bool TableEstimate::overlaps(const TableEstimate& o, const TBaselineParams& p) const
{
	const double halfDiagonal = std::hypot(p.table_length + p.leg_width, p.table_width + p.leg_width) / 2;
	if ((centre - o.centre).norm() > 2 * halfDiagonal) return false;
	auto footprint = [&](const TableEstimate& t) {
		return world::Obstacle::rectangle(
			t.centre, t.yaw, (p.table_length + p.leg_width) / 2, (p.table_width + p.leg_width) / 2, 0);
	};
	return footprint(*this).intersects(footprint(o));
}

void TableEstimate::fitToContacts(
	const std::vector<LegFit>& fits, const std::vector<Contact>& all, const TBaselineParams& p)
{
	std::vector<FaceResidual::Member> members;
	texture = 0;
	for (int k = 0; k < 4; k++)
		if (legs[k] >= 0)
			for (size_t i : fits[legs[k]].members) members.push_back({i, offset(k, p)}), texture += all[i].texture;
	contacts = members.size();
	texture /= double(std::max<size_t>(1, contacts));
	const auto res = FaceResidual::fitPose(all, members, Eigen::Vector3d(centre.x(), centre.y(), yaw), p);
	cost = res.cost;
	centre = res.x.head<2>(), yaw = res.x[2];
}
}  // namespace whiskermap::baseline
