#include <fcntl.h>
#include <octomap/OcTree.h>
#include <unistd.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/render/OcTreeExport.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>

namespace whiskermap::render
{
namespace
{
/** OctoMap's writer prints progress on stderr ("Writing N nodes ... done."): silence it
 *  for the scope, so apps print only what they mean to. */
class QuietStderr
{
   public:
	QuietStderr() : m_saved(::dup(STDERR_FILENO))
	{
		const int null = ::open("/dev/null", O_WRONLY);
		if (null >= 0) ::dup2(null, STDERR_FILENO), ::close(null);
	}
	~QuietStderr()
	{
		if (m_saved >= 0) ::dup2(m_saved, STDERR_FILENO), ::close(m_saved);
	}
	QuietStderr(const QuietStderr&) = delete;
	QuietStderr& operator=(const QuietStderr&) = delete;

   private:
	int m_saved;
};
}  // namespace

double OcTreeExport::range(double resolution) { return resolution * 32767; }

size_t OcTreeExport::write(const std::vector<world::Table>& tables, const TOptions& o, const std::string& path)
{
	return write(tables, {}, o, path);
}

size_t OcTreeExport::write(
	const std::vector<world::Table>& tables, const std::vector<world::Obstacle>& walls, const TOptions& o,
	const std::string& path)
{
	octomap::OcTree tree(o.resolution);
	size_t occupied = 0;
	const double r = o.resolution;
	for (const auto& w : walls)
	{
		double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
		for (const auto& c : w.corners)
			x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x()), y0 = std::min(y0, c.y()), y1 = std::max(y1, c.y());
		if (std::max({-x0, x1, -y0, y1}) >= range(r)) throw core::Error(path + ": a wall lies beyond the octree's range");
		const auto cell = [&](double v) { return static_cast<int64_t>(std::floor(v / r)); };
		for (int64_t i = cell(x0); (i + 0.5) * r <= x1; i++)
			for (int64_t j = cell(y0); (j + 0.5) * r <= y1; j++)
			{
				const double x = (i + 0.5) * r, y = (j + 0.5) * r;
				if (w.distance(Eigen::Vector2d(x, y)) > 0) continue;
				for (int64_t k = 0; (k + 0.5) * r <= o.height; k++, occupied++)
					tree.updateNode(octomap::point3d(float(x), float(y), float((k + 0.5) * r)), true);
			}
	}
	for (const auto& t : tables)
	{
		std::array<world::Obstacle, 4> legs;
		for (int k = 0; k < 4; k++) legs[k] = t.leg(k, 0);
		const auto top = t.footprint();
		// Voxel centres on the tree's own grid (multiples of r, offset by r/2), over the
		// footprint's bounding box.
		double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
		for (const auto& c : top.corners)
			x0 = std::min(x0, c.x()), x1 = std::max(x1, c.x()), y0 = std::min(y0, c.y()), y1 = std::max(y1, c.y());
		if (std::max({-x0, x1, -y0, y1}) >= range(r))
			throw core::Error(
				path + ": a table at (" + std::to_string(t.x) + ", " + std::to_string(t.y) +
				") lies beyond the octree's range of +-" + std::to_string(range(r)) + " m at resolution " +
				std::to_string(r) + " m");
		// Integer voxel indices (a floating-point x += r stops advancing far from the origin).
		const auto cell = [&](double v) { return static_cast<int64_t>(std::floor(v / r)); };
		for (int64_t i = cell(x0); (i + 0.5) * r <= x1; i++)
			for (int64_t j = cell(y0); (j + 0.5) * r <= y1; j++)
			{
				const double x = (i + 0.5) * r, y = (j + 0.5) * r;
				const Eigen::Vector2d p(x, y);
				if (top.distance(p) > 0) continue;
				bool inLeg = false;
				for (const auto& l : legs) inLeg = inLeg || l.distance(p) == 0;
				for (int64_t k = 0; (k + 0.5) * r <= o.height; k++)
				{
					const double z = (k + 0.5) * r;
					const bool inTop = z >= o.height - o.topThickness;
					if (!inLeg && !inTop) continue;
					tree.updateNode(octomap::point3d(float(x), float(y), float(z)), true);
					occupied++;
				}
			}
	}
	tree.updateInnerOccupancy();
	const std::string tmp = path + ".tmp";
	bool written;
	{
		QuietStderr quiet;
		written = tree.writeBinary(tmp);
	}
	if (!written) throw core::Error(path + ": cannot write octree");
	std::filesystem::rename(tmp, path);
	return occupied;
}
}  // namespace whiskermap::render
