#include <whiskermap/core/Angles.h>
#include <whiskermap/maps/SweepLikelihood.h>
#include <whiskermap/world/WhiskerContact.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::maps
{
double SweepLikelihood::sweptBoundary(
	const model::SweptGrid& grid, double x, double y, double length, double start, double stop, double stopReach,
	const std::vector<std::pair<int32_t, int32_t>>& legCells, const TOptions& o)
{
	// The boundary of the swept sector, one sample a cell apart: the tip's arc, the shaft at
	// the start and the shaft where it stopped, up to its contact (a solid crossing the
	// sector crosses its boundary). Every sample counts (not every distinct cell), so that a
	// small shift of the pose changes the sum only where samples cross into other cells.
	// Cells holding a mapped leg are left to the leg term.
	const double cell = grid.cellSize();
	double ll = 0;
	size_t samples = 0, unexplored = 0;
	const auto add = [&](double a, double r) {
		const int32_t ix = grid.index(x + r * std::cos(a)), iy = grid.index(y + r * std::sin(a));
		samples++;
		if (std::find(legCells.begin(), legCells.end(), std::make_pair(ix, iy)) != legCells.end()) return;
		const auto c = grid.atIndex(ix, iy);
		if (!c.explored())
			unexplored++;
		else
			ll += std::log((1 - touchChance(c, o)) / (1 - o.cell_prior));  // eq. L3
	};
	const double r = length - cell / 2;
	const int arc = 1 + static_cast<int>(std::ceil(std::abs(stop - start) * r / cell));
	for (int k = 0; k < arc; k++) add(start + (stop - start) * k / arc, r);
	for (double s = cell / 2; s < r; s += cell) add(start, s);
	for (double s = cell / 2; s < std::min(r, stopReach - cell / 2); s += cell) add(stop, s);
	return ll + std::log(o.p_unexplored) * static_cast<double>(unexplored) / static_cast<double>(samples);  // eq. L5
}

double SweepLikelihood::logLikelihood(
	const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& robotPose,
	const std::vector<world::Obstacle>& solids, const TOptions& o, const model::SweptGrid* grid)
{
	if (!o.use_swept_grid) grid = nullptr;
	const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(robotPose) + sweep.sensorPose;
	const double yaw = sensor.yaw();
	std::vector<world::Obstacle> near;
	std::vector<std::pair<int32_t, int32_t>> legCells;
	double ll = 0;
	if (grid && !grid->empty() && !grid->at(robotPose.x(), robotPose.y()).explored())
		ll += std::log(o.p_unexplored);  // eq. L4
	for (const auto& w : sweep.whiskers)
	{
		double px, py, pz;
		sensor.composePoint(w.mount_x, w.mount_y, 0, px, py, pz);
		const Eigen::Vector2d pivot(px, py);
		near.clear();
		for (const auto& s : solids)
			if ((s.corners[0] - pivot).norm() <= w.length + (s.corners[2] - s.corners[0]).norm())
				near.push_back(s);
		const auto predicted =
			world::WhiskerContact::first(pivot, w.length, yaw + w.sweep_start, yaw + w.sweep_end, near);
		const Eigen::Vector2d seen =
			pivot + w.r * Eigen::Vector2d(std::cos(yaw + w.angle), std::sin(yaw + w.angle));
		double pu = o.p_unexplained;
		if (grid && !grid->empty())
		{
			// eq. L2; a contact the legs predict is theirs: the grid's touches there are that
			// leg's, so they may lower p_u (free space) but not raise it
			if (w.touched)
				pu = std::min(predicted ? pu : 1.0, pu * touchChance(grid->at(seen.x(), seen.y()), o) / o.cell_prior);
			const double stop = w.touched ? w.angle : w.sweep_end;
			legCells.clear();
			for (const auto& s : near)
			{
				// A leg's cell is its centre's; a wall's, every cell along its centre line.
				Eigen::Vector2d a = (s.corners[0] + s.corners[2]) / 2, b = a;
				if (s.table < 0)
				{
					const bool firstLonger =
						(s.corners[1] - s.corners[0]).squaredNorm() >= (s.corners[2] - s.corners[1]).squaredNorm();
					const auto mid = [&](int i, int j) -> Eigen::Vector2d { return (s.corners[i] + s.corners[j]) / 2; };
					a = firstLonger ? mid(0, 3) : mid(0, 1), b = firstLonger ? mid(1, 2) : mid(2, 3);
				}
				const int n = static_cast<int>(std::ceil((b - a).norm() / (grid->cellSize() / 2)));
				for (int k = 0; k <= n; k++)
				{
					const Eigen::Vector2d p = n ? Eigen::Vector2d(a + (b - a) * (double(k) / n)) : a;
					legCells.emplace_back(grid->index(p.x()), grid->index(p.y()));
				}
			}
			if (stop != w.sweep_start)
				ll += sweptBoundary(
					*grid, px, py, w.length, yaw + w.sweep_start, yaw + stop, w.touched ? w.r : w.length, legCells, o);
		}
		if (w.touched && predicted)
		{
			const double d2 = (seen - predicted->point).squaredNorm();
			const double a = core::wrapToPi(yaw + w.normal - predicted->normal);
			ll += std::log(
				(1 - o.p_unexplained) * std::exp(-d2 / (2 * o.sigma_contact * o.sigma_contact) -
												 a * a / (2 * o.sigma_normal * o.sigma_normal)) +
				pu);
		}
		else if (w.touched)
			ll += std::log(pu);
		else if (predicted)
			ll += std::log(o.p_miss);
	}
	return ll;
}
}  // namespace whiskermap::maps
