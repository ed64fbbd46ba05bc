#include <whiskermap/model/GridFreeSpace.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace whiskermap::model
{
double GridFreeSpace::logWallFactor(const Wall& w, const SweptGrid& grid, const ModelParams& p)
{
	// The cells the centre line crosses: samples a quarter cell apart, each cell once.
	const double step = grid.cellSize() / 4;
	const auto n = std::min(static_cast<long>(std::ceil(w.length() / step)), 1L << 14);  // 400 m at 0.1 m cells
	std::vector<std::pair<int32_t, int32_t>> cells;
	cells.reserve(static_cast<size_t>(n) + 1);
	for (long k = 0; k <= n; k++)
	{
		const double f = n == 0 ? 0 : static_cast<double>(k) / static_cast<double>(n);
		const std::pair<int32_t, int32_t> c{
			grid.index(w.x0 + f * (w.x1 - w.x0)), grid.index(w.y0 + f * (w.y1 - w.y0))};
		if (cells.empty() || cells.back() != c) cells.push_back(c);
	}
	std::sort(cells.begin(), cells.end());
	cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
	const double perPass = std::log((1 + p.free_space_p_miss) / 2);  // eq. 25
	double sum = 0;
	for (const auto& [ix, iy] : cells)
	{
		const SweptGrid::Cell c = grid.atIndex(ix, iy);
		if (c.touches == 0) sum += c.passes * perPass;
	}
	return sum;
}
}  // namespace whiskermap::model
