#include <sys/resource.h>

#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <whiskermap/cli/MapOutputs.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/maps/MapCsv.h>
#include <whiskermap/render/OcTreeExport.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace whiskermap::cli
{
namespace
{
using mrpt::img::TColor;
const TColor TRUTH(0, 0, 200), ESTIMATE(200, 40, 40), POSES(150, 150, 150), CONTACTS(0, 150, 0);
const char* MOVE_NAMES[inference::MOVE_COUNT] = {"priming", "death", "reparent", "child", "parent", "refit"};

double percentile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[static_cast<size_t>(std::min<double>(v.size() - 1, std::floor(q * (v.size() - 1) + 0.5)))];
}

void drawTruth(render::TopDownImage& img, const world::World* w)
{
	if (!w) return;
	img.arena(*w, {0, 0, 0});
	for (const auto& t : w->tables) img.table(t, TRUTH, 2);
}

/** A blackboard (the paper's figs. 1-2): its tables, legs and the working-memory contacts. */
void drawBlackboard(
	const maps::CHierarchicalObjectMap& map, const model::HypothesisSet& bb,
	const std::vector<obs::Shapelet>& memory, const std::string& caption, const std::string& path)
{
	double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
	for (const auto& s : memory)
		x0 = std::min(x0, s.x), x1 = std::max(x1, s.x), y0 = std::min(y0, s.y), y1 = std::max(y1, s.y);
	if (memory.empty()) x0 = y0 = 0, x1 = y1 = 1;
	render::TopDownImage img(x0 - 1.2, x1 + 1.2, y0 - 1.2, y1 + 1.2, 250);
	for (const auto& t : bb.tables) img.table(map.toWorldTable(t), ESTIMATE, 1);
	for (const auto& l : bb.legs)
		img.quad(world::Obstacle::rectangle({l.x, l.y}, l.theta, l.wx / 2, l.wy / 2, 0).corners, TRUTH, 2);
	for (const auto& s : memory) img.shapelet(s, CONTACTS);
	img.caption(caption);
	img.caption(std::to_string(bb.tables.size()) + " tables (red), " + std::to_string(bb.legs.size()) +
				" legs (blue), " + std::to_string(memory.size()) + " contacts (green)");
	img.save(path);
}

std::string indent(std::string json)
{
	for (size_t p = json.find('\n'); p != std::string::npos && p + 1 < json.size(); p = json.find('\n', p + 1))
		json.insert(p + 1, "  ");
	return json.substr(0, json.find_last_not_of('\n') + 1);
}
}  // namespace

void MapOutputs::pictureBounds(const std::string& input, const world::World* w, TSettings& s)
{
	if (w)
	{
		s.x0 = w->x_min, s.x1 = w->x_max, s.y0 = w->y_min, s.y1 = w->y_max;
		return;
	}
	s.x0 = s.y0 = 1e18, s.x1 = s.y1 = -1e18;
	double reach = 0;
	obs::RawlogReader::forEach(input, [&](const obs::RawlogReader::Sweep& sw) {
		s.x0 = std::min(s.x0, sw.robotPose.x()), s.x1 = std::max(s.x1, sw.robotPose.x());
		s.y0 = std::min(s.y0, sw.robotPose.y()), s.y1 = std::max(s.y1, sw.robotPose.y());
		for (const auto& wh : sw.obs->whiskers)
			reach = std::max(reach, std::hypot(wh.mount_x, wh.mount_y) + wh.length);
	});
	const double margin = reach + 0.2;
	s.x0 -= margin, s.x1 += margin, s.y0 -= margin, s.y1 += margin;
}

MapOutputs::MapOutputs(OutputDir& out, const maps::CHierarchicalObjectMap& map, const TSettings& s)
	: m_out(out),
	  m_map(map),
	  m_s(s),
	  m_montage(s.x0, s.x1, s.y0, s.y1),
	  m_contacts(s.x0, s.x1, s.y0, s.y1)
{
	if (m_map.lasting()) return;
	m_perPose.emplace(out.path("per_pose_tables.csv"));
	if (s.world) m_eval.emplace(s.world->tables, eval::EvalOptions{}, true);
}

void MapOutputs::onStep(size_t index, const obs::RawlogReader::Sweep& sweep, double ms)
{
	const auto& rec = m_map.lastRecord();
	const auto& shapelets = m_map.lastInput().shapelets;
	if (m_perPose)
	{
		m_perPose->add(index, rec);
		m_montage.robot(rec.pose, POSES);
		for (const auto& t : rec.tables) m_montage.table(t, ESTIMATE, 1);
	}
	else if (m_map.lastLastingStats().changed)
	{
		m_insertions++;
		m_visited += m_map.lastLastingStats().visited;
		m_board += m_map.lastLastingStats().boardHypotheses;
	}
	for (const auto& sh : shapelets)
	{
		m_contacts.shapelet(sh, CONTACTS);
		m_shapelets.add(sh);
	}
	m_path.add(rec.pose);
	if (m_eval) m_eval->add(rec.tables, rec.pose);
	if (m_s.world || m_s.simpleMap) m_kept.push_back(sweep);
	m_ms.push_back(ms);
	m_steps++;
	m_shapeletCount += shapelets.size();
	m_tables += rec.tables.size();
	m_maxTables = std::max(m_maxTables, rec.tables.size());
	if (static_cast<int>(index) == m_s.snapshotPose) drawSnapshot(index);
}

void MapOutputs::drawSnapshot(size_t index)
{
	const auto& step = m_map.lastStep();
	const auto& memory = m_map.lastInput().memory;
	const std::string k = std::to_string(index), t = std::to_string(m_s.snapshotTemperature);
	if (step.snapshot)
	{
		if (!m_s.quiet)
			std::printf(
				"whisker-map: sweep %zu: %zu tables, %zu legs at temperature index %d; MAP: %zu tables\n", index,
				step.snapshot->tables.size(), step.snapshot->legs.size(), m_s.snapshotTemperature,
				step.map.tables.size());
		char beta[32];
		std::snprintf(beta, sizeof(beta), "%.3g", m_map.samplerParams.schedule[m_s.snapshotTemperature]);
		drawBlackboard(
			m_map, *step.snapshot, memory, "pose " + k + ": blackboard at temperature index " + t + " (beta " + beta + ")",
			m_out.path("blackboard_pose" + k + "_t" + t + ".png"));
	}
	drawBlackboard(
		m_map, step.map, memory, "pose " + k + ": MAP blackboard at the coldest temperature",
		m_out.path("blackboard_pose" + k + "_map.png"));
}

double MapOutputs::medianMs() const { return percentile(m_ms, 0.5); }

void MapOutputs::writeScene(const std::string& path) const
{
	mrpt::opengl::COpenGLScene scene;
	scene.insert(mrpt::opengl::CGridPlaneXY::Create(
		std::floor(m_s.x0), std::ceil(m_s.x1), std::floor(m_s.y0), std::ceil(m_s.y1), 0, 0.5));
	auto objs = mrpt::opengl::CSetOfObjects::Create();
	objs->setName("whiskermap");
	m_map.getVisualizationInto(*objs);
	scene.insert(objs);
	auto contacts = mrpt::opengl::CPointCloud::Create();
	contacts->setName("contacts");
	for (const auto& s : m_shapelets.items()) contacts->insertPoint(s.x, s.y, 0.05);
	contacts->setColor(0.1f, 0.6f, 0.1f);
	contacts->setPointSize(3);
	scene.insert(contacts);
	auto path3d = mrpt::opengl::CSetOfLines::Create();
	path3d->setName("robot_path");
	const auto& poses = m_path.items();
	for (size_t i = 1; i < poses.size(); i++)
		path3d->appendLine(poses[i - 1].x(), poses[i - 1].y(), 0.01, poses[i].x(), poses[i].y(), 0.01);
	path3d->setColor(0.5f, 0.5f, 0.5f);
	scene.insert(path3d);
	if (!scene.saveToFile(path)) throw core::Error(path + ": cannot write 3-D scene");
}

std::string MapOutputs::finish(double wallSeconds)
{
	const auto objects = m_map.mapObjects();  // the map, computed once
	std::vector<world::Table> mapped;
	for (const auto& o : objects) mapped.push_back(o.table);
	const auto candidates = m_map.candidateObjects();
	maps::MapCsv::writeObjects(m_out.path("map_tables.csv"), objects);
	maps::MapCsv::writeObjects(m_out.path("map_candidates.csv"), candidates);

	const std::string source = std::filesystem::path(m_s.input).filename().string();
	if (m_perPose)
	{
		m_perPose->close();
		drawTruth(m_montage, m_s.world);
		m_montage.caption(source + ": per-pose MAP tables (red), poses (grey)" + (m_s.world ? ", truth (blue)" : ""));
		m_montage.save(m_out.path("montage.png"));
	}

	drawTruth(m_contacts, m_s.world);
	for (const auto& t : mapped) m_contacts.table(t, ESTIMATE, 2);
	char threshold[64];
	if (m_map.lasting())
		std::snprintf(threshold, sizeof(threshold), "existence >= %g", m_map.likelihoodOptions.min_existence);
	else
		std::snprintf(threshold, sizeof(threshold), "support >= %u", m_map.likelihoodOptions.min_support);
	m_contacts.caption(
		source + ": map of " + std::to_string(mapped.size()) + " tables, " + threshold + " (red), contacts (green)" +
		(m_s.world ? ", truth (blue)" : ""));
	m_contacts.save(m_out.path("map.png"));

	writeScene(m_out.path("map.3Dscene"));
	const auto& ro = m_map.renderOptions;
	render::OcTreeExport::write(
		mapped, {ro.octomap_resolution, ro.table_height, ro.top_thickness}, m_out.path("map.bt"));
	if (m_s.simpleMap)
	{
		mrpt::maps::CSimpleMap sm;
		for (const auto& s : m_kept)
		{
			auto sf = mrpt::obs::CSensoryFrame::Create();
			sf->insert(s.obs);
			sm.insert(mrpt::poses::CPose3DPDFGaussian::Create(mrpt::poses::CPose3D(s.robotPose)), sf);
		}
		if (!sm.saveToFile(m_out.path("map.simplemap"))) throw core::Error("map.simplemap: cannot write");
	}

	std::string metricsJson, text;
	if (m_s.world)
	{
		eval::EvalReport r;
		r.map = eval::MapEvaluation::compute(m_s.world->tables, mapped, r.options);
		if (m_eval) r.perPose = m_eval->result();
		r.identifiability =
			eval::Identifiability::of(*m_s.world, m_kept, eval::Identifiability::defaultGate(m_kept));
		metricsJson = r.toJson();
		text = r.toText();
		std::ofstream f(m_out.path("metrics.json"));
		f << metricsJson;
		if (!f) throw core::Error("metrics.json: write failed");
	}
	writeSummary(m_out.path(m_s.summaryName), wallSeconds, mapped.size(), candidates.size(), metricsJson);
	return text;
}

void MapOutputs::writeSummary(
	const std::string& path, double wallSeconds, size_t mapped, size_t candidates, const std::string& metricsJson) const
{
	double totalMs = 0;
	uint64_t proposals = 0;
	for (double t : m_ms) totalMs += t;
	for (auto n : m_map.proposed()) proposals += n;
	rusage usage{};
	::getrusage(RUSAGE_SELF, &usage);
	std::ofstream f(path);
	char buf[256];
	f << "{\n";
	f << "  \"input\": \"" << m_s.input << "\",\n  \"config\": \"" << m_s.config << "\",\n";
	f << "  \"seed\": " << m_map.insertionOptions.seed << ",\n  \"jobs\": " << m_s.jobs << ",\n";
	f << "  \"mode\": \"" << (m_map.lasting() ? "lasting" : "per_pose") << "\",\n";
	f << "  \"poses\": " << m_steps << ",\n  \"shapelets\": " << m_shapeletCount << ",\n";
	if (m_map.lasting())
	{
		const auto& st = m_map.lastingMap().state();
		std::snprintf(buf, sizeof(buf),
					  "  \"local_problem\": {\"insertions\": %llu, \"mean_visited\": %.2f, \"mean_hypotheses\": %.2f},\n",
					  static_cast<unsigned long long>(m_insertions), m_insertions ? double(m_visited) / m_insertions : 0.0,
					  m_insertions ? double(m_board) / m_insertions : 0.0);
		f << buf;
		f << "  \"state\": {\"tables\": " << st.tableCount() << ", \"legs\": " << st.legCount()
		  << ", \"explicit_contacts\": " << st.contactCount() << "},\n";
	}
	else
	{
		std::snprintf(buf, sizeof(buf), "  \"tables_per_pose\": {\"mean\": %.4f, \"max\": %zu},\n",
					  m_steps ? double(m_tables) / m_steps : 0.0, m_maxTables);
		f << buf;
	}
	f << "  \"map_tables\": " << mapped << ",\n  \"map_candidates\": " << candidates << ",\n";
	f << "  \"moves\": {";
	for (size_t k = 0; k < inference::MOVE_COUNT; k++)
		f << (k ? ", " : "") << "\"" << MOVE_NAMES[k] << "\": {\"proposed\": " << m_map.proposed()[k]
		  << ", \"accepted\": " << m_map.accepted()[k] << "}";
	f << "},\n";
	std::snprintf(buf, sizeof(buf), "  \"time_per_pose_ms\": {\"median\": %.4f, \"p95\": %.4f},\n",
				  percentile(m_ms, 0.5), percentile(m_ms, 0.95));
	f << buf;
	std::snprintf(buf, sizeof(buf), "  \"proposals_per_second\": %.0f,\n", totalMs > 0 ? proposals / (totalMs / 1000) : 0.0);
	f << buf;
	std::snprintf(buf, sizeof(buf), "  \"wall_time_s\": %.3f,\n  \"peak_rss_mb\": %.1f", wallSeconds,
				  usage.ru_maxrss / 1024.0);
	f << buf;
	if (!metricsJson.empty()) f << ",\n  \"metrics\": " << indent(metricsJson);
	f << "\n}\n";
	if (!f) throw core::Error(path + ": write failed");
}
}  // namespace whiskermap::cli
