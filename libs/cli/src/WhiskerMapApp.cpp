#include <unistd.h>

#include <CLI/CLI.hpp>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/opengl/CGridPlaneXY.h>
#include <mrpt/opengl/COpenGLScene.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <whiskermap/cli/OutputDir.h>
#include <whiskermap/cli/WhiskerMapApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/maps/MapCsv.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/render/OcTreeExport.h>
#include <whiskermap/render/TopDownImage.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

namespace whiskermap::cli
{
namespace
{
using mrpt::img::TColor;
const TColor TRUTH(0, 0, 200), ESTIMATE(200, 40, 40), POSES(150, 150, 150), CONTACTS(0, 150, 0);
const char* MOVE_NAMES[] = {"priming", "death", "reparent", "child", "parent"};

struct Options
{
	std::string input, config, outdir, world;
	std::optional<uint64_t> seed;
	int snapshotPose = -1, snapshotTemperature = 0;
	bool quiet = false;
};

std::string fmtBeta(double b)
{
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%.3g", b);
	return buf;
}

double percentile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[static_cast<size_t>(std::min<double>(v.size() - 1, std::floor(q * (v.size() - 1) + 0.5)))];
}

/** Region to draw: the arena when known, else everything the map holds, padded. */
render::TopDownImage canvas(const maps::CHierarchicalObjectMap& map, const world::World* w)
{
	if (w) return render::TopDownImage(w->x_min, w->x_max, w->y_min, w->y_max);
	const auto bb = map.boundingBox();
	return render::TopDownImage(bb.min.x - 0.5, bb.max.x + 0.5, bb.min.y - 0.5, bb.max.y + 0.5);
}

void drawTruth(render::TopDownImage& img, const world::World* w)
{
	if (!w) return;
	img.arena(*w, {0, 0, 0});
	for (const auto& t : w->tables) img.table(t, TRUTH, 2);
}

/** The paper's fig. 5 style collation: every per-pose MAP table over the arena. */
void drawMontage(const maps::CHierarchicalObjectMap& map, const world::World* w, const std::string& title, const std::string& path)
{
	auto img = canvas(map, w);
	for (const auto& p : map.poseRecords()) img.robot(p.pose, POSES);
	for (const auto& p : map.poseRecords())
		for (const auto& t : p.tables) img.table(t, ESTIMATE, 1);
	drawTruth(img, w);
	img.caption(title + ": MAP tables of every pose (red), robot poses (grey)" + (w ? ", truth (blue)" : ""));
	img.save(path);
}

/** The consolidated map: objects with enough support, and every contact. */
void drawMap(const maps::CHierarchicalObjectMap& map, const world::World* w, const std::string& path)
{
	auto img = canvas(map, w);
	for (const auto& s : map.shapelets()) img.shapelet(s, CONTACTS);
	drawTruth(img, w);
	size_t shown = 0;
	for (const auto& o : map.objects())
		if (o.support >= map.likelihoodOptions.min_support)
			img.table(o.table, ESTIMATE, o.existence() >= 0.5 ? 3 : 1), shown++;
	img.caption(
		"consolidated map: " + std::to_string(shown) + " objects with support >= " +
		std::to_string(map.likelihoodOptions.min_support) + " (red; thick: existence >= 0.5), contacts (green)" +
		(w ? ", truth (blue)" : ""));
	img.save(path);
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
	img.caption(std::to_string(bb.tables.size()) + " tables (red), " + std::to_string(bb.legs.size()) + " legs (blue), " +
				std::to_string(memory.size()) + " contacts (green)");
	img.save(path);
}

void writeScene(const maps::CHierarchicalObjectMap& map, const std::string& path)
{
	mrpt::opengl::COpenGLScene scene;
	const auto bb = map.boundingBox();
	scene.insert(mrpt::opengl::CGridPlaneXY::Create(
		std::floor(bb.min.x), std::ceil(bb.max.x), std::floor(bb.min.y), std::ceil(bb.max.y), 0, 0.5));
	auto objs = mrpt::opengl::CSetOfObjects::Create();
	objs->setName("whiskermap");
	map.getVisualizationInto(*objs);
	scene.insert(objs);
	auto path3d = mrpt::opengl::CSetOfLines::Create();
	path3d->setName("robot_path");
	const auto& poses = map.poseRecords();
	for (size_t i = 1; i < poses.size(); i++)
		path3d->appendLine(poses[i - 1].pose.x(), poses[i - 1].pose.y(), 0.01, poses[i].pose.x(), poses[i].pose.y(), 0.01);
	path3d->setColor(0.5f, 0.5f, 0.5f);
	scene.insert(path3d);
	if (!scene.saveToFile(path)) throw core::Error(path + ": cannot write 3-D scene");
}

/** The sweeps with their poses as a CSimpleMap: MRPT apps (pf-localization, the map
 *  builders) rebuild the map from it with the same [MetricMap] .ini. */
void writeSimpleMap(const obs::RawlogReader::Contents& rawlog, const std::string& path)
{
	mrpt::maps::CSimpleMap sm;
	for (const auto& s : rawlog.sweeps)
	{
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(s.obs);
		sm.insert(mrpt::poses::CPose3DPDFGaussian::Create(mrpt::poses::CPose3D(s.robotPose)), sf);
	}
	if (!sm.saveToFile(path)) throw core::Error(path + ": cannot write simple map");
}

/** The evaluation against ground truth (whisker-eval's figures, doc/evaluation.md) of the
 *  consolidated map's objects with enough support and of the per-pose MAPs. */
eval::EvalReport evaluate(
	const world::World& w, const maps::CHierarchicalObjectMap& map, const obs::RawlogReader::Contents& rawlog)
{
	eval::EvalReport r;
	r.map = eval::MapEvaluation::compute(w.tables, map.supportedTables(), r.options);
	std::vector<std::vector<world::Table>> perPose;
	std::vector<mrpt::poses::CPose2D> poses;
	for (const auto& p : map.poseRecords()) perPose.push_back(p.tables), poses.push_back(p.pose);
	r.perPose = eval::PerPoseEvaluation::compute(w.tables, perPose, poses, r.options);
	r.identifiability =
		eval::Identifiability::of(w, rawlog.sweeps, eval::Identifiability::defaultGate(rawlog.sweeps));
	return r;
}

void writeSummary(
	const std::string& path, const Options& o, const maps::CHierarchicalObjectMap& map,
	const std::vector<double>& ms, const std::optional<eval::EvalReport>& metrics)
{
	std::ofstream f(path);
	const auto& poses = map.poseRecords();
	size_t tables = 0, maxTables = 0;
	const size_t supported = map.supportedTables().size();
	for (const auto& p : poses) tables += p.tables.size(), maxTables = std::max(maxTables, p.tables.size());
	double totalMs = 0;
	uint64_t proposals = 0;
	for (double t : ms) totalMs += t;
	for (auto n : map.proposed()) proposals += n;
	char buf[256];
	f << "{\n";
	f << "  \"input\": \"" << o.input << "\",\n  \"config\": \"" << o.config << "\",\n";
	f << "  \"seed\": " << map.insertionOptions.seed << ",\n";
	f << "  \"poses\": " << poses.size() << ",\n  \"shapelets\": " << map.shapelets().size() << ",\n";
	std::snprintf(buf, sizeof(buf), "  \"tables_per_pose\": {\"mean\": %.4f, \"max\": %zu},\n",
				  poses.empty() ? 0.0 : double(tables) / poses.size(), maxTables);
	f << buf;
	f << "  \"map_objects\": " << map.objects().size() << ",\n  \"map_objects_supported\": " << supported << ",\n";
	f << "  \"moves\": {";
	for (size_t k = 0; k < inference::MOVE_COUNT; k++)
		f << (k ? ", " : "") << "\"" << MOVE_NAMES[k] << "\": {\"proposed\": " << map.proposed()[k]
		  << ", \"accepted\": " << map.accepted()[k] << "}";
	f << "},\n";
	std::snprintf(buf, sizeof(buf), "  \"time_per_pose_ms\": {\"median\": %.4f, \"p95\": %.4f},\n",
				  percentile(ms, 0.5), percentile(ms, 0.95));
	f << buf;
	std::snprintf(buf, sizeof(buf), "  \"proposals_per_second\": %.0f", totalMs > 0 ? proposals / (totalMs / 1000) : 0.0);
	f << buf;
	if (metrics)
	{
		std::string j = metrics->toJson();  // indent the nested object
		for (size_t p = j.find('\n'); p != std::string::npos && p + 1 < j.size(); p = j.find('\n', p + 1))
			j.insert(p + 1, "  ");
		f << ",\n  \"metrics\": " << j.substr(0, j.find_last_not_of('\n') + 1);
	}
	f << "\n}\n";
	if (!f) throw core::Error(path + ": write failed");
}

int run(Options& o)
{
	// Everything that can be wrong with the inputs is checked before any output is made.
	if (o.config.empty()) o.config = core::ConfigPaths::find("whisker-map.ini");
	mrpt::maps::CMultiMetricMap multimap(maps::MapConfig::load(o.config));
	auto map = multimap.mapByClass<maps::CHierarchicalObjectMap>();
	if (!map) throw core::Error(o.config + ": no hierarchicalObjectMap was created (is libwhiskermap-maps loaded?)");
	if (o.seed) map->insertionOptions.seed = *o.seed;
	std::optional<world::World> world;
	if (!o.world.empty()) world = world::World::load(o.world);
	const auto rawlog = obs::RawlogReader::read(o.input);
	if (rawlog.sweeps.empty())
		throw core::Error(o.input + ": holds no whisker observations (CObservationWhiskerContacts)");
	if (o.snapshotTemperature >= static_cast<int>(map->samplerParams.schedule.size()))
		throw core::Error("--snapshot-temperature " + std::to_string(o.snapshotTemperature) + ": the schedule has only " +
						  std::to_string(map->samplerParams.schedule.size()) + " temperatures");
	if (o.snapshotPose >= static_cast<int>(rawlog.sweeps.size()))
		throw core::Error("--snapshot-pose " + std::to_string(o.snapshotPose) + ": the rawlog has only " +
						  std::to_string(rawlog.sweeps.size()) + " sweeps");

	OutputDir out(o.outdir);
	const bool bar = !o.quiet && ::isatty(STDERR_FILENO);
	std::vector<double> ms;
	const size_t n = rawlog.sweeps.size();
	for (size_t i = 0; i < n; i++)
	{
		const auto& s = rawlog.sweeps[i];
		const bool snap = static_cast<int>(i) == o.snapshotPose;
		map->setSnapshotTemperature(snap ? o.snapshotTemperature : -1);
		const auto t0 = std::chrono::steady_clock::now();
		multimap.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
		if (snap)
		{
			const auto& step = map->lastStep();
			const auto memory = std::vector<obs::Shapelet>(  // the step's working memory
				map->shapelets().end() - std::min<size_t>(map->shapelets().size(), map->insertionOptions.memory_size),
				map->shapelets().end());
			const std::string k = std::to_string(i);
			if (step.snapshot && !o.quiet)
				std::printf("whisker-map: sweep %zu: %zu tables, %zu legs at temperature index %d; MAP: %zu tables\n", i,
							step.snapshot->tables.size(), step.snapshot->legs.size(), o.snapshotTemperature,
							step.map.tables.size());
			if (step.snapshot)
				drawBlackboard(*map, *step.snapshot, memory, "pose " + k + ": blackboard at temperature index " + std::to_string(o.snapshotTemperature) + " (beta " + fmtBeta(map->samplerParams.schedule[o.snapshotTemperature]) + ")",
							   out.path("blackboard_pose" + k + "_t" + std::to_string(o.snapshotTemperature) + ".png"));
			drawBlackboard(*map, step.map, memory, "pose " + k + ": MAP blackboard at the coldest temperature",
						   out.path("blackboard_pose" + k + "_map.png"));
		}
		if (bar && (i % 10 == 0 || i + 1 == n))
		{
			const int w = 30, done = static_cast<int>(w * (i + 1) / n);
			std::fprintf(stderr, "\rwhisker-map: [%s%s] %zu/%zu sweeps", std::string(done, '#').c_str(),
						 std::string(w - done, '.').c_str(), i + 1, n);
			if (i + 1 == n) std::fprintf(stderr, "\n");
		}
	}

	const world::World* w = world ? &*world : nullptr;
	maps::MapCsv::writePerPose(out.path("per_pose_tables.csv"), map->poseRecords());
	maps::MapCsv::writeObjects(out.path("map_tables.csv"), map->objects());
	drawMontage(*map, w, std::filesystem::path(o.input).filename().string(), out.path("montage.png"));
	drawMap(*map, w, out.path("map.png"));
	writeScene(*map, out.path("map.3Dscene"));
	writeSimpleMap(rawlog, out.path("map.simplemap"));
	const auto& ro = map->renderOptions;
	render::OcTreeExport::write(map->supportedTables(), {ro.octomap_resolution, ro.table_height, ro.top_thickness}, out.path("map.bt"));
	std::optional<eval::EvalReport> metrics;
	if (w)
	{
		metrics = evaluate(*w, *map, rawlog);
		std::ofstream(out.path("metrics.json")) << metrics->toJson();
	}
	writeSummary(out.path("summary.json"), o, *map, ms, metrics);
	out.commit();
	if (metrics && !o.quiet) std::printf("%s", metrics->toText().c_str());
	if (!o.quiet)
		std::printf("whisker-map: %zu sweeps -> %s (%s); median %.3f ms per sweep\n", n,
					o.outdir.c_str(), map->asString().c_str(), percentile(ms, 0.5));
	return 0;
}
}  // namespace

int WhiskerMapApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-map: map tables from whisker contacts. Runs a CHierarchicalObjectMap (Fox & "
		"Prescott's hierarchical model and annealed blackboard sampler) over every whisker sweep "
		"of a rawlog (either MRPT layout) and writes, in OUTDIR: per_pose_tables.csv, "
		"map_tables.csv, montage.png, map.png, map.3Dscene, map.bt (OctoMap), map.simplemap, summary.json (doc/outputs.md)."};
	Options o;
	app.add_option("-i,--input", o.input, "Input rawlog with CObservationWhiskerContacts sweeps")->required();
	app.add_option("-c,--config", o.config, "CMultiMetricMap .ini (default: the shipped config/whisker-map.ini)");
	app.add_option("-o,--out", o.outdir, "Output folder (created; files in it are replaced only when the run succeeds)")->required();
	app.add_option("--seed", o.seed, "Override the map's base seed (insertOpts seed); same seed, same maps");
	app.add_option("--world", o.world,
				   "Ground-truth world .ini: drawn in the pictures, and the maps are evaluated against it "
				   "(metrics.json, and \"metrics\" in summary.json; doc/evaluation.md)");
	app.add_option("--snapshot-pose", o.snapshotPose,
				   "Also draw the blackboard of this sweep (0-based) at a hot temperature and its MAP "
				   "(the paper's figs. 1-2)");
	app.add_option("--snapshot-temperature", o.snapshotTemperature,
				   "Schedule index (0 = hottest) of the --snapshot-pose blackboard picture")
		->check(CLI::NonNegativeNumber)
		->capture_default_str();
	app.add_flag("-q,--quiet", o.quiet, "Print nothing but errors");
	return runApp(app, argc, argv, "whisker-map", [&] { return run(o); });
}
}  // namespace whiskermap::cli
