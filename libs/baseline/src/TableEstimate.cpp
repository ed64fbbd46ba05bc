#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/baseline/LeastSquares.h>
#include <whiskermap/baseline/TableEstimate.h>
#include <whiskermap/world/Obstacle.h>

#include <Eigen/Geometry>
#include <algorithm>

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
	auto footprint = [&](const TableEstimate& t) {
		return world::Obstacle::rectangle(
			t.centre, t.yaw, (p.table_length + p.leg_width) / 2, (p.table_width + p.leg_width) / 2, 0);
	};
	return footprint(*this).intersects(footprint(o));
}

void TableEstimate::fitToContacts(
	const std::vector<LegFit>& fits, const std::vector<Contact>& all, const TBaselineParams& p)
{
	std::vector<std::pair<size_t, int>> members;  // (contact, corner)
	texture = 0;
	for (int k = 0; k < 4; k++)
		if (legs[k] >= 0)
			for (size_t i : fits[legs[k]].members) members.emplace_back(i, k), texture += all[i].texture;
	contacts = members.size();
	texture /= double(std::max<size_t>(1, contacts));
	Eigen::Vector3d x(centre.x(), centre.y(), yaw);
	auto legCentre = [&](const Eigen::Vector3d& v, int k) {
		return Eigen::Vector2d(v.head<2>() + Eigen::Rotation2Dd(v[2]) * offset(k, p));
	};
	std::vector<int> faces(members.size());
	auto assignFaces = [&] {
		bool changed = false;
		for (size_t j = 0; j < members.size(); j++)
		{
			const auto& [i, k] = members[j];
			const int f = FaceResidual::best(all[i], legCentre(x, k), x[2], p).face;
			changed = changed || f != faces[j];
			faces[j] = f;
		}
		return changed;
	};
	const auto residuals = [&](const Eigen::Vector3d& v, std::vector<double>& out) {
		out.clear();
		for (size_t j = 0; j < members.size(); j++)
		{
			const auto& [i, k] = members[j];
			const auto r = FaceResidual::on(all[i], legCentre(v, k), v[2], faces[j], p);
			out.push_back(LeastSquares::huber(r.point));
			out.push_back(LeastSquares::huber(r.normal));
			out.push_back(LeastSquares::huber(r.beyond));
		}
	};
	assignFaces();
	for (int round = 0; round < 4; round++)
	{
		const auto res = LeastSquares::solve(x, residuals);
		x = res.x, cost = res.cost;
		if (!assignFaces()) break;
	}
	centre = x.head<2>(), yaw = x[2];
}
}  // namespace whiskermap::baseline
