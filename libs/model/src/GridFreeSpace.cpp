#include <whiskermap/model/Densities.h>
#include <whiskermap/model/GridFreeSpace.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace whiskermap::model
{
double GridFreeSpace::logWallFactor(const Wall& w, const SweptGrid& grid, const ModelParams& p)
{
	// The cells the centre line crosses: samples a quarter cell apart. Along a straight line
	// both cell indices only grow or only shrink, so a cell's samples are consecutive: each
	// cell is counted once by skipping a sample in the cell of the one before.
	const double step = grid.cellSize() / 4;
	const auto n = std::min(static_cast<long>(std::ceil(w.length() / step)), 1L << 14);  // 400 m at 0.1 m cells
	const double perPass = std::log((1 + p.free_space_p_miss) / 2);  // eq. 25
	double sum = 0;
	std::pair<int32_t, int32_t> previous;
	for (long k = 0; k <= n; k++)
	{
		const double f = n == 0 ? 0 : static_cast<double>(k) / static_cast<double>(n);
		const std::pair<int32_t, int32_t> cell{
			grid.index(w.x0 + f * (w.x1 - w.x0)), grid.index(w.y0 + f * (w.y1 - w.y0))};
		if (k > 0 && cell == previous) continue;
		previous = cell;
		const SweptGrid::Cell c = grid.atIndex(cell.first, cell.second);
		if (c.touches == 0) sum += c.passes * perPass;
	}
	return sum;
}

double GridFreeSpace::logLegFactor(double x, double y, double w, const SweptGrid& grid, const ModelParams& p)
{
	const SweptGrid::Cell centre = grid.atIndex(grid.index(x), grid.index(y));
	if (centre.passes == 0 || centre.touches > 0) return 0;
	// Where the leg's own contacts would fall: within w / 2 of its centre, plus the readings' noise.
	const double reach = std::min(w / 2 + 2 * p.sigma_r, 1.0);
	for (int32_t ix = grid.index(x - reach); ix <= grid.index(x + reach); ix++)
		for (int32_t iy = grid.index(y - reach); iy <= grid.index(y + reach); iy++)
			if (grid.atIndex(ix, iy).touches > 0) return 0;
	const double hit = std::min(1.0, w / (2 * grid.cellSize()));
	return centre.passes * std::log(1 - (1 - p.free_space_p_miss) * hit);  // eq. 27
}

double GridFreeSpace::logEmptyCorners(const Table& t, const CornerCounts& counts, const SweptGrid& grid, const ModelParams& p)
{
	double x[4], y[4], sum = 0;
	tableCorners(t, p, x, y);
	for (int k = 0; k < 4; k++)
		if (counts[static_cast<size_t>(k)] == 0) sum += logLegFactor(x[k], y[k], t.leg_width, grid, p);
	return sum;
}
}  // namespace whiskermap::model
