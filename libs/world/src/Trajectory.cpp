#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/Trajectory.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace whiskermap::world
{
std::vector<mrpt::poses::CPose2D> Trajectory::paperGrid(const World& w, int n) { return paperGrid(w, n, n); }

std::vector<mrpt::poses::CPose2D> Trajectory::paperGrid(const World& w, int nx, int ny)
{
	std::vector<mrpt::poses::CPose2D> poses;
	const double dx = (w.x_max - w.x_min) / nx, dy = (w.y_max - w.y_min) / ny;
	for (int row = 0; row < ny; row++)
		for (int col = 0; col < nx; col++)
			for (int h = 0; h < 4; h++)
				poses.emplace_back(
					w.x_min + (col + 0.5) * dx, w.y_min + (row + 0.5) * dy, h * M_PI / 2);
	return poses;
}

std::vector<mrpt::poses::CPose2D> Trajectory::readPathFile(const std::string& path, std::vector<int>* lines)
{
	if (lines) lines->clear();
	std::ifstream f(path);
	if (!f) throw core::Error(path + ": cannot open path file");
	std::vector<mrpt::poses::CPose2D> poses;
	std::string line;
	for (int lineNo = 1; std::getline(f, line); lineNo++)
	{
		const auto b = line.find_first_not_of(" \t\r");
		if (b == std::string::npos || line[b] == '%' || line[b] == '#') continue;
		std::istringstream s(line);
		double x, y, yawDeg;
		std::string extra;
		if (!(s >> x >> y >> yawDeg) || (s >> extra) || !std::isfinite(x) || !std::isfinite(y) ||
			!std::isfinite(yawDeg))
			throw core::Error(
				path + ": line " + std::to_string(lineNo) + ": expected 'x y yaw_deg', got '" +
				line + "'");
		poses.emplace_back(x, y, core::deg2rad(yawDeg));
		if (lines) lines->push_back(lineNo);
	}
	if (poses.empty()) throw core::Error(path + ": path file holds no poses");
	return poses;
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
}  // namespace whiskermap::world
