#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/LineReader.h>
#include <whiskermap/world/Trajectory.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace whiskermap::world
{
namespace
{
class GridSource : public PoseSource
{
   public:
	GridSource(const World& w, int nx, int ny) : m_w(w), m_nx(nx), m_ny(ny)
	{
		if (nx < 1 || ny < 1) throw core::Error("paper grid: needs at least 1 x 1 positions");
	}
	bool next(mrpt::poses::CPose2D& p) override
	{
		if (m_i == size()) return false;
		const size_t h = m_i % 4, cell = m_i / 4, col = cell % size_t(m_nx), row = cell / size_t(m_nx);
		const double dx = (m_w.x_max - m_w.x_min) / m_nx, dy = (m_w.y_max - m_w.y_min) / m_ny;
		p = mrpt::poses::CPose2D(m_w.x_min + (col + 0.5) * dx, m_w.y_min + (row + 0.5) * dy, h * M_PI / 2);
		m_i++;
		return true;
	}
	void rewind() override { m_i = 0; }
	size_t size() const override { return 4 * size_t(m_nx) * size_t(m_ny); }

   private:
	World m_w;
	int m_nx, m_ny;
	size_t m_i = 0;
};

class PathFileSource : public PoseSource
{
   public:
	explicit PathFileSource(const std::string& path) : m_path(path)
	{
		mrpt::poses::CPose2D p;
		while (next(p)) m_size++;  // the whole file checked up front
		if (m_size == 0) throw core::Error(path + ": path file holds no poses");
		rewind();
	}
	bool next(mrpt::poses::CPose2D& p) override
	{
		std::string line;
		while (m_in->next(line))
		{
			const auto b = line.find_first_not_of(" \t");
			if (b == std::string::npos || line[b] == '%' || line[b] == '#') continue;
			std::istringstream s(line);
			double x, y, yawDeg;
			std::string extra;
			const double lim = Trajectory::MAX_COORDINATE;
			if (!(s >> x >> y >> yawDeg) || (s >> extra) || !(std::abs(x) <= lim) || !(std::abs(y) <= lim) ||
				!(std::abs(yawDeg) <= 3600))
				throw core::Error(
					m_in->where() + "expected 'x y yaw_deg' (|x|, |y| <= 1e5 m, |yaw_deg| <= 3600), got '" + line + "'");
			p = mrpt::poses::CPose2D(x, y, core::deg2rad(yawDeg));
			return true;
		}
		return false;
	}
	void rewind() override { m_in = std::make_unique<core::LineReader>(m_path, "path file"); }
	size_t size() const override { return m_size; }
	std::string where() const override { return m_in->where(); }
	size_t lineNo() const { return m_in->lineNo(); }

   private:
	std::string m_path;
	std::unique_ptr<core::LineReader> m_in = std::make_unique<core::LineReader>(m_path, "path file");
	size_t m_size = 0;
};

class VectorSource : public PoseSource
{
   public:
	explicit VectorSource(std::vector<mrpt::poses::CPose2D> poses) : m_poses(std::move(poses)) {}
	bool next(mrpt::poses::CPose2D& p) override
	{
		if (m_i == m_poses.size()) return false;
		p = m_poses[m_i++];
		return true;
	}
	void rewind() override { m_i = 0; }
	size_t size() const override { return m_poses.size(); }

   private:
	std::vector<mrpt::poses::CPose2D> m_poses;
	size_t m_i = 0;
};

std::vector<mrpt::poses::CPose2D> all(PoseSource& s)
{
	std::vector<mrpt::poses::CPose2D> v;
	mrpt::poses::CPose2D p;
	while (s.next(p)) v.push_back(p);
	return v;
}
}  // namespace

std::vector<mrpt::poses::CPose2D> Trajectory::paperGrid(const World& w, int n) { return paperGrid(w, n, n); }

std::vector<mrpt::poses::CPose2D> Trajectory::paperGrid(const World& w, int nx, int ny)
{
	return all(*paperGridSource(w, nx, ny));
}

std::unique_ptr<PoseSource> Trajectory::paperGridSource(const World& w, int nx, int ny)
{
	return std::make_unique<GridSource>(w, nx, ny);
}

void Trajectory::writePathFile(
	const std::string& path, const std::vector<mrpt::poses::CPose2D>& poses, const std::string& comment)
{
	std::ofstream f(path);
	if (!f) throw core::Error(path + ": cannot write path file");
	std::istringstream lines(comment);
	for (std::string line; std::getline(lines, line);) f << "# " << line << "\n";
	char buf[128];
	for (const auto& p : poses)
	{
		std::snprintf(buf, sizeof(buf), "%.10g %.10g %.10g\n", p.x(), p.y(), core::rad2deg(p.phi()));
		f << buf;
	}
	if (!f) throw core::Error(path + ": write failed");
}
std::unique_ptr<PoseSource> Trajectory::pathFileSource(const std::string& path)
{
	return std::make_unique<PathFileSource>(path);
}

std::unique_ptr<PoseSource> Trajectory::vectorSource(std::vector<mrpt::poses::CPose2D> poses)
{
	return std::make_unique<VectorSource>(std::move(poses));
}

std::vector<mrpt::poses::CPose2D> Trajectory::readPathFile(const std::string& path, std::vector<size_t>* lines)
{
	PathFileSource s(path);
	if (lines) lines->clear();
	std::vector<mrpt::poses::CPose2D> v;
	mrpt::poses::CPose2D p;
	while (s.next(p))
	{
		v.push_back(p);
		if (lines) lines->push_back(s.lineNo());
	}
	return v;
}
}  // namespace whiskermap::world
