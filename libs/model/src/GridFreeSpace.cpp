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
}  // namespace whiskermap::model
