#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <whiskermap/cli/MapOutputs.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/peakRssMb.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/eval/ObjectsOnWalls.h>
#include <whiskermap/maps/MapCsv.h>
#include <whiskermap/render/OcTreeExport.h>

#include <nlohmann/json.hpp>

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

/** A wall of the map as a solid (pictures, octree). */
world::Obstacle wallSolid(const model::Wall& w)
{
	const model::OrientedRect r = w.rect();
	return world::Obstacle::rectangle({r.cx, r.cy}, r.theta, r.hx, r.hy, w.texture);
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

}  // namespace

void MapOutputs::pictureBounds(const obs::RawlogReader::Summary& in, const world::World* w, TSettings& s)
{
	if (w)
	{
		s.x0 = w->x_min, s.x1 = w->x_max, s.y0 = w->y_min, s.y1 = w->y_max;
		return;
	}
	const double margin = in.maxReach + 0.2;
	s.x0 = in.x0 - margin, s.x1 = in.x1 + margin, s.y0 = in.y0 - margin, s.y1 = in.y1 + margin;
}

MapOutputs::MapOutputs(OutputDir& out, const maps::CHierarchicalObjectMap& map, const TSettings& s)
	: m_out(out),
	  m_map(map),
	  m_s(s),
	  m_montage(s.x0, s.x1, s.y0, s.y1),
	  m_contacts(s.x0, s.x1, s.y0, s.y1)
{
	if (s.world) m_ident.emplace(*s.world, eval::Identifiability::gateFor(s.maxSigmaR));
	if (s.simpleMap) m_simpleMap.emplace(out.path("map.simplemap"), static_cast<uint32_t>(s.sweeps));
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
	if (m_ident) m_ident->add(sweep);
	if (m_simpleMap) m_simpleMap->add(sweep.robotPose, sweep.obs);
	m_ms.add(ms);
	m_totalMs += ms;
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

double MapOutputs::medianMs() const { return percentile(m_ms.items(), 0.5); }

void MapOutputs::writeScene(const std::string& path) const
{
	mrpt::opengl::COpenGLScene scene;
	scene.insert(mrpt::opengl::CGridPlaneXY::Create(
		std::floor(m_s.x0), std::ceil(m_s.x1), std::floor(m_s.y0), std::ceil(m_s.y1), 0, 0.5));
	auto objs = mrpt::opengl::CSetOfObjects::Create();
	objs->setName("whiskermap");
	m_map.getVisualizationInto(*objs);
	scene.insert(objs);
	for (const auto& w : m_map.mapWalls())  // the map's walls as boxes up to the table height
	{
		const model::OrientedRect r = w.wall.rect();
		auto box = mrpt::opengl::CBox::Create(
			mrpt::math::TPoint3D(-r.hx, -r.hy, 0), mrpt::math::TPoint3D(r.hx, r.hy, m_map.renderOptions.table_height));
		box->setPose(mrpt::poses::CPose3D(r.cx, r.cy, 0, r.theta, 0, 0));
		box->setColor(0.6f, 0.6f, 0.6f);
		box->setName("wall");
		scene.insert(box);
	}
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
	const bool spreads = m_map.lasting();  // the lasting map reports each object's pose spread
	const auto objects = m_map.mapObjects(spreads);  // the map, computed once
	std::vector<world::Table> mapped;
	for (const auto& o : objects) mapped.push_back(o.table);
	const auto candidates = m_map.candidateObjects(spreads);
	const bool withClass = !m_map.modelParams.classes.empty();
	maps::MapCsv::writeObjects(m_out.path("map_tables.csv"), objects, withClass, spreads);
	maps::MapCsv::writeObjects(m_out.path("map_candidates.csv"), candidates, withClass, spreads);
	std::vector<world::Obstacle> walls;  // the map's walls, when the model has them
	for (const auto& w : m_map.mapWalls()) walls.push_back(wallSolid(w.wall));
	if (m_map.modelParams.walls) maps::MapCsv::writeWalls(m_out.path("map_walls.csv"), m_map.mapWalls());

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
	for (const auto& w : walls) m_contacts.quad(w.corners, ESTIMATE, 2);
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
		mapped, walls, {ro.octomap_resolution, ro.table_height, ro.top_thickness}, m_out.path("map.bt"));
	if (m_simpleMap) m_simpleMap->close();

	std::string metricsJson, text;
	if (m_s.world)
	{
		eval::EvalReport r;
		r.map = eval::MapEvaluation::compute(m_s.world->tables, mapped, r.options, withClass);
		r.objectsOnWalls = eval::ObjectsOnWalls::of(*m_s.world, mapped).size();
		if (m_eval) r.perPose = m_eval->result();
		r.identifiability = m_ident->result();
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
	uint64_t proposals = 0;
	for (auto n : m_map.proposed()) proposals += n;
	const auto fixed = [](double v, int decimals) { return std::round(v * std::pow(10, decimals)) / std::pow(10, decimals); };
	nlohmann::ordered_json j;  // a JSON writer: any path (quotes, backslashes) stays valid JSON
	j["input"] = m_s.input;
	j["config"] = m_s.config;
	j["seed"] = m_map.insertionOptions.seed;
	j["jobs"] = m_s.jobs;
	j["mode"] = m_map.lasting() ? "lasting" : "per_pose";
	j["poses"] = m_steps;
	j["shapelets"] = m_shapeletCount;
	if (m_map.lasting())
	{
		const auto& st = m_map.lastingMap().state();
		const double n = m_insertions ? double(m_insertions) : 1.0;
		j["local_problem"] = {
			{"insertions", m_insertions}, {"mean_visited", fixed(m_visited / n, 2)}, {"mean_hypotheses", fixed(m_board / n, 2)}};
		j["state"] = {{"tables", st.tableCount()}, {"legs", st.legCount()}, {"explicit_contacts", st.contactCount()}};
	}
	else
		j["tables_per_pose"] = {{"mean", fixed(m_steps ? double(m_tables) / m_steps : 0.0, 4)}, {"max", m_maxTables}};
	j["map_tables"] = mapped;
	j["map_candidates"] = candidates;
	auto& moves = j["moves"] = nlohmann::ordered_json::object();
	for (size_t k = 0; k < inference::MOVE_COUNT; k++)
		moves[MOVE_NAMES[k]] = {{"proposed", m_map.proposed()[k]}, {"accepted", m_map.accepted()[k]}};
	// The same per move type (the sampler's MoveRegistry lines), with the acceptance rate.
	auto& types = j["move_types"] = nlohmann::ordered_json::object();
	for (const inference::MoveTally& t : m_map.moveTypes())
		types[t.name] = {
			{"proposed", t.proposed}, {"accepted", t.accepted},
			{"acceptance_rate", fixed(t.proposed ? double(t.accepted) / double(t.proposed) : 0.0, 4)}};
	j["time_per_pose_ms"] = {{"median", fixed(percentile(m_ms.items(), 0.5), 4)}, {"p95", fixed(percentile(m_ms.items(), 0.95), 4)}};
	j["proposals_per_second"] = std::round(m_totalMs > 0 ? proposals / (m_totalMs / 1000) : 0.0);
	j["wall_time_s"] = fixed(wallSeconds, 3);
	j["peak_rss_mb"] = fixed(core::peakRssMb(), 1);
	if (!metricsJson.empty()) j["metrics"] = nlohmann::ordered_json::parse(metricsJson);
	std::ofstream f(path);
	f << j.dump(2) << "\n";
	if (!f) throw core::Error(path + ": write failed");
}
}  // namespace whiskermap::cli
