#include <fcntl.h>
#include <octomap/OcTree.h>
#include <unistd.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/render/OcTreeExport.h>

#include <cmath>
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

size_t OcTreeExport::write(const std::vector<world::Table>& tables, const TOptions& o, const std::string& path)
{
	octomap::OcTree tree(o.resolution);
	size_t occupied = 0;
	const double r = o.resolution;
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
		auto first = [&](double v) { return (std::floor(v / r) + 0.5) * r; };
		for (double x = first(x0); x <= x1; x += r)
			for (double y = first(y0); y <= y1; y += r)
			{
				const Eigen::Vector2d p(x, y);
				if (top.distance(p) > 0) continue;
				bool inLeg = false;
				for (const auto& l : legs) inLeg = inLeg || l.distance(p) == 0;
				for (double z = first(0); z <= o.height; z += r)
				{
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
