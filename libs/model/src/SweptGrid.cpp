#include <whiskermap/model/SweptGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace whiskermap::model
{
namespace
{
int32_t floorDiv(int32_t a, int32_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
using Key = std::pair<int32_t, int32_t>;
void bump(uint16_t& n)
{
	if (n < std::numeric_limits<uint16_t>::max()) n++;
}
}  // namespace

SweptGrid::SweptGrid(double cellSize) { clear(cellSize); }

void SweptGrid::clear(double cellSize)
{
	if (!(cellSize > 0)) throw std::invalid_argument("SweptGrid: the cell size must be > 0");
	m_cell = cellSize;
	m_cx0 = m_cy0 = m_w = m_h = 0;
	m_chunks.clear();
}

int32_t SweptGrid::index(double v) const { return static_cast<int32_t>(std::floor(v / m_cell)); }

SweptGrid::Cell SweptGrid::atIndex(int32_t ix, int32_t iy) const
{
	const int32_t cx = floorDiv(ix, CHUNK) - m_cx0, cy = floorDiv(iy, CHUNK) - m_cy0;
	if (cx < 0 || cy < 0 || cx >= m_w || cy >= m_h) return {};
	const auto& chunk = m_chunks[static_cast<size_t>(cy * m_w + cx)];
	if (!chunk) return {};
	return (*chunk)[static_cast<size_t>((iy - floorDiv(iy, CHUNK) * CHUNK) * CHUNK + ix - floorDiv(ix, CHUNK) * CHUNK)];
}

SweptGrid::Cell SweptGrid::at(double x, double y) const { return atIndex(index(x), index(y)); }

void SweptGrid::grow(int32_t cx, int32_t cy)
{
	const int32_t x0 = m_chunks.empty() ? cx : std::min(m_cx0, cx), y0 = m_chunks.empty() ? cy : std::min(m_cy0, cy);
	const int32_t x1 = m_chunks.empty() ? cx : std::max(m_cx0 + m_w - 1, cx);
	const int32_t y1 = m_chunks.empty() ? cy : std::max(m_cy0 + m_h - 1, cy);
	std::vector<std::shared_ptr<Chunk>> grown(static_cast<size_t>((x1 - x0 + 1) * (y1 - y0 + 1)));
	for (int32_t y = 0; y < m_h; y++)
		for (int32_t x = 0; x < m_w; x++)
			grown[static_cast<size_t>((y + m_cy0 - y0) * (x1 - x0 + 1) + x + m_cx0 - x0)] =
				std::move(m_chunks[static_cast<size_t>(y * m_w + x)]);
	m_chunks = std::move(grown);
	m_cx0 = x0, m_cy0 = y0, m_w = x1 - x0 + 1, m_h = y1 - y0 + 1;
}

SweptGrid::Cell& SweptGrid::writable(int32_t ix, int32_t iy)
{
	const int32_t cx = floorDiv(ix, CHUNK), cy = floorDiv(iy, CHUNK);
	if (m_chunks.empty() || cx < m_cx0 || cy < m_cy0 || cx >= m_cx0 + m_w || cy >= m_cy0 + m_h) grow(cx, cy);
	auto& chunk = m_chunks[static_cast<size_t>((cy - m_cy0) * m_w + cx - m_cx0)];
	if (!chunk)
		chunk = std::make_shared<Chunk>();
	else if (chunk.use_count() > 1)  // shared with a copy: copy on write
		chunk = std::make_shared<Chunk>(*chunk);
	return (*chunk)[static_cast<size_t>((iy - cy * CHUNK) * CHUNK + ix - cx * CHUNK)];
}

void SweptGrid::addSweep(
	double robotX, double robotY, const std::vector<obs::SweptSector>& sectors,
	const std::vector<std::array<double, 2>>& contacts)
{
	std::vector<Key> passed{{index(robotX), index(robotY)}}, touched;
	const double step = m_cell / 2;  // samples half a cell apart cover every cell crossed
	for (const auto& s : sectors)
		for (double r = step / 2; r < s.radius; r += step)
		{
			const int n = 1 + static_cast<int>(std::ceil(s.span * r / step));
			for (int k = 0; k <= n; k++)
			{
				const double a = s.from + s.span * k / n;
				passed.emplace_back(index(s.x + r * std::cos(a)), index(s.y + r * std::sin(a)));
			}
		}
	for (const auto& c : contacts) touched.emplace_back(index(c[0]), index(c[1]));
	std::sort(passed.begin(), passed.end());
	std::sort(touched.begin(), touched.end());
	touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
	passed.erase(std::unique(passed.begin(), passed.end()), passed.end());
	for (const auto& [ix, iy] : touched) bump(writable(ix, iy).touches);
	for (const auto& k : passed)
		if (!std::binary_search(touched.begin(), touched.end(), k)) bump(writable(k.first, k.second).passes);
}

std::vector<SweptGrid::IndexedCell> SweptGrid::cells() const
{
	std::vector<IndexedCell> out;
	for (int32_t cy = 0; cy < m_h; cy++)
		for (int32_t cx = 0; cx < m_w; cx++)
		{
			const auto& chunk = m_chunks[static_cast<size_t>(cy * m_w + cx)];
			if (!chunk) continue;
			for (int32_t k = 0; k < CHUNK * CHUNK; k++)
				if ((*chunk)[static_cast<size_t>(k)].explored())
					out.push_back({(cx + m_cx0) * CHUNK + k % CHUNK, (cy + m_cy0) * CHUNK + k / CHUNK,
								   (*chunk)[static_cast<size_t>(k)]});
		}
	return out;
}

void SweptGrid::set(int32_t ix, int32_t iy, Cell c) { writable(ix, iy) = c; }

size_t SweptGrid::chunkCount() const
{
	return static_cast<size_t>(std::count_if(m_chunks.begin(), m_chunks.end(), [](const auto& c) { return c != nullptr; }));
}

size_t SweptGrid::sharedChunks() const
{
	return static_cast<size_t>(
		std::count_if(m_chunks.begin(), m_chunks.end(), [](const auto& c) { return c && c.use_count() > 1; }));
}
}  // namespace whiskermap::model
