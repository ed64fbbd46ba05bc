#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/MapCsv.h>
#include <whiskermap/maps/PerPoseCsvWriter.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

namespace whiskermap::maps
{
namespace
{
void writeFile(const std::string& path, const char* header, const std::function<void(FILE*)>& rows)
{
	const std::string tmp = path + ".tmp";
	FILE* f = std::fopen(tmp.c_str(), "w");
	if (!f) throw core::Error(path + ": cannot create file");
	std::fprintf(f, "%s\n", header);
	rows(f);
	const bool ok = std::ferror(f) == 0;
	if (std::fclose(f) != 0 || !ok) throw core::Error(path + ": write failed");
	std::filesystem::rename(tmp, path);
}

void writeTable(FILE* f, const world::Table& t)
{
	std::fprintf(
		f, "%.6f,%.6f,%.4f,%.6f,%.6f,%.6f,%.4f", t.x, t.y, core::rad2deg(t.yaw), t.length, t.width,
		t.leg_width, t.texture);
}
}  // namespace

void MapCsv::writeWalls(const std::string& path, const std::vector<model::LastingState::StoredWall>& walls)
{
	writeFile(path, "x0,y0,x1,y1,thickness,existence", [&](FILE* f) {
		for (const auto& w : walls)
			std::fprintf(
				f, "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", w.wall.x0, w.wall.y0, w.wall.x1, w.wall.y1, w.wall.thickness,
				w.existence);
	});
}

void MapCsv::writeObjects(
	const std::string& path, const std::vector<TMappedObject>& objects, bool withClass, bool withSpread)
{
	const std::string header = std::string("id,x,y,yaw_deg,length,width,leg_width,texture,existence,contacts,legs") +
							   (withSpread ? ",sd_x,sd_y,sd_yaw_deg" : "") + (withClass ? ",class" : "");
	writeFile(path, header.c_str(), [&](FILE* f) {
		for (size_t i = 0; i < objects.size(); i++)
		{
			std::fprintf(f, "%zu,", i);
			writeTable(f, objects[i].table);
			std::fprintf(
				f, ",%.4f,%llu,%u", objects[i].existence, static_cast<unsigned long long>(objects[i].contacts),
				objects[i].legs);
			const TMappedObject& o = objects[i];
			if (withSpread && !(std::isfinite(o.sd_x) && std::isfinite(o.sd_y) && std::isfinite(o.sd_yaw)))
				throw core::Error(path + ": object " + std::to_string(i) + " has no pose spread (sd_x, sd_y, sd_yaw)");
			if (withSpread) std::fprintf(f, ",%.6f,%.6f,%.4f", o.sd_x, o.sd_y, o.sd_yaw * 180 / M_PI);
			std::fprintf(f, withClass ? ",%s\n" : "\n", objects[i].table.object_class.str().c_str());
		}
	});
}

void MapCsv::writePerPose(const std::string& path, const std::vector<TPoseRecord>& poses)
{
	PerPoseCsvWriter w(path);
	for (size_t i = 0; i < poses.size(); i++) w.add(i, poses[i]);
	w.close();
}

PerPoseCsvWriter::PerPoseCsvWriter(const std::string& path) : m_path(path)
{
	m_file = std::fopen((path + ".tmp").c_str(), "w");
	if (!m_file) throw core::Error(path + ": cannot create file");
	std::fprintf(m_file, "pose,x,y,yaw_deg,length,width,leg_width,texture,log_posterior\n");
}

PerPoseCsvWriter::~PerPoseCsvWriter()
{
	if (!m_file) return;
	std::fclose(m_file);
	std::remove((m_path + ".tmp").c_str());
}

void PerPoseCsvWriter::add(size_t index, const TPoseRecord& pose)
{
	for (const auto& t : pose.tables)
	{
		std::fprintf(m_file, "%zu,", index);
		writeTable(m_file, t);
		std::fprintf(m_file, ",%.6f\n", pose.logPosterior);
	}
}

void PerPoseCsvWriter::close()
{
	const bool ok = std::ferror(m_file) == 0;
	const bool closed = std::fclose(m_file) == 0;
	m_file = nullptr;
	if (!ok || !closed) throw core::Error(m_path + ": write failed");
	std::filesystem::rename(m_path + ".tmp", m_path);
}
}  // namespace whiskermap::maps
