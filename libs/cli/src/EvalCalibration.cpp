#include <whiskermap/cli/EvalCalibration.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/TableCsv.h>
#include <whiskermap/render/TopDownImage.h>
#include <whiskermap/world/World.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace whiskermap::cli
{
eval::Calibration EvalCalibration::ofMap(
	const std::string& world, const std::string& map, const std::string& candidates,
	const eval::EvalOptions& opts, eval::SpreadCoverage* spread)
{
	const auto w = world::World::load(world);
	bool hasClass = false;
	auto rows = eval::TableCsv::readMap(map, &hasClass);
	if (spread) spread->add(eval::SpreadCoverage::of(w.tables, rows, opts, hasClass));
	if (!candidates.empty())
	{
		bool candClass = false;
		const auto more = eval::TableCsv::readMap(candidates, &candClass);
		if (candClass != hasClass)
			throw core::Error(candidates + ": the class column must be present in both " + map + " and it, or in neither");
		rows.insert(rows.end(), more.begin(), more.end());
	}
	return eval::Calibration::of(w.tables, rows, opts, hasClass);
}

eval::Calibration EvalCalibration::ofRuns(const std::string& list, const eval::EvalOptions& opts, eval::SpreadCoverage* spread)
{
	std::ifstream f(list);
	if (!f) throw core::Error(list + ": no such file");
	eval::Calibration pooled;
	std::string line;
	size_t n = 0, runs = 0;
	while (std::getline(f, line))
	{
		n++;
		std::istringstream in(line);
		std::string world, map, candidates, extra;
		if (!(in >> world) || world[0] == '#') continue;
		if (!(in >> map) || ((in >> candidates) && (in >> extra)))
			throw core::Error(list + ": line " + std::to_string(n) + ": expected 'WORLD MAP [CANDIDATES]'");
		// relative paths are relative to the list's folder
		const auto at = [&](const std::string& file) {
			return file.empty() || std::filesystem::path(file).is_absolute() ? file : (std::filesystem::path(list).parent_path() / file).string();
		};
		pooled.add(ofMap(at(world), at(map), at(candidates), opts, spread));
		runs++;
	}
	if (runs == 0) throw core::Error(list + ": no run listed");
	return pooled;
}

void EvalCalibration::plot(const eval::Calibration& c, const std::string& title, const std::string& png)
{
	using V = Eigen::Vector2d;
	render::TopDownImage img(-0.05, 1.05, -0.05, 1.05, 500);  // the captions go above (TopDownImage::caption)
	const mrpt::img::TColor black(0, 0, 0), grey(160, 160, 160), bar(140, 180, 230), dot(200, 30, 30);
	for (size_t i = 0; i < eval::Calibration::BINS; i++)
	{
		const auto& b = c.bins()[i];
		if (b.count == 0) continue;
		const double lo = static_cast<double>(i) / eval::Calibration::BINS, w = 1.0 / eval::Calibration::BINS;
		const double h = b.fractionReal();
		for (double x = lo + 0.004; x < lo + w - 0.002; x += 0.003)  // bar, filled by hatching
			img.quad({V(x, 0), V(x, h), V(x, h), V(x, 0)}, bar);
		img.quad({V(lo, 0), V(lo + w, 0), V(lo + w, h), V(lo, h)}, black);
		const double m = b.meanExistence(), r = 0.008;
		for (double d = -r; d <= r; d += 0.002) img.quad({V(m - r, h + d), V(m + r, h + d), V(m + r, h + d), V(m - r, h + d)}, dot);
	}
	img.quad({V(0, 0), V(1, 0), V(1, 1), V(0, 1)}, black, 2);
	img.quad({V(0, 0), V(1, 1), V(1, 1), V(0, 0)}, grey);  // perfect calibration
	for (int k = 1; k < 10; k++)
	{
		img.quad({V(k / 10.0, 0), V(k / 10.0, -0.02), V(k / 10.0, -0.02), V(k / 10.0, 0)}, black);
		img.quad({V(0, k / 10.0), V(-0.02, k / 10.0), V(-0.02, k / 10.0), V(0, k / 10.0)}, black);
	}
	char buf[120];
	img.caption(std::filesystem::path(title).filename().string());
	std::snprintf(buf, sizeof(buf), "%zu objects, %zu real, ECE %.3f", c.count(), c.real(), c.ece());
	img.caption(buf);
	img.caption("x: reported existence (ticks 0.1), y: fraction real");
	std::string counts = "red: bin mean; grey: perfect; per bin:";
	for (const auto& b : c.bins()) counts += " " + std::to_string(b.count);
	img.caption(counts);
	img.save(png);
}
}  // namespace whiskermap::cli
