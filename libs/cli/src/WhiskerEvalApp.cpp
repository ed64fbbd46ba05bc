#include <CLI/CLI.hpp>
#include <whiskermap/cli/EvalCalibration.h>
#include <whiskermap/cli/WhiskerEvalApp.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/eval/ObjectsOnWalls.h>
#include <whiskermap/eval/TableCsv.h>
#include <whiskermap/eval/TouchedWalls.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/PathLog.h>

#include <iostream>
#include <optional>

namespace whiskermap::cli
{
namespace
{
struct Options
{
	std::string world, map, walls, perPose, rawlog, path, truth;
	std::string candidates, calibrationRuns, plot;  // calibration
	size_t poses = 0;
	bool json = false, calibration = false;
	eval::EvalOptions eval;
};

/** Prints the report; draws the reliability plot first when asked (it may fail: no output). */
int print(const Options& o, const eval::EvalReport& r)
{
	if (!o.plot.empty()) EvalCalibration::plot(*r.calibration, o.calibrationRuns.empty() ? o.map : o.calibrationRuns, o.plot);
	std::cout << (o.json ? r.toJson() : r.toText());
	return 0;
}

/** A report holding what `fill` puts in it, printed. */
template <class Fill>
int printWith(const Options& o, Fill fill)
{
	eval::EvalReport r;
	r.options = o.eval;
	fill(r);
	return print(o, r);
}

int run(const Options& o)
{
	o.eval.validate();
	if (!o.calibrationRuns.empty())
	{
		if (!o.map.empty() || !o.path.empty() || !o.world.empty() || !o.candidates.empty())
			throw core::Error("--calibration-runs pools the maps it lists: give no --map, --candidates, --world or --path");
		return printWith(o, [&](eval::EvalReport& r) {
			eval::SpreadCoverage spread;
			r.calibration = EvalCalibration::ofRuns(o.calibrationRuns, o.eval, &spread);
			if (spread.count() > 0) r.spread = spread;
		});
	}
	if (!o.candidates.empty() && !o.calibration) throw core::Error("--candidates is pooled with --map for --calibration: give --calibration");
	if (!o.plot.empty() && !o.calibration) throw core::Error("--reliability-plot draws --calibration or --calibration-runs: give one");
	if (o.calibration && o.map.empty()) throw core::Error("--calibration scores a map's existences: give --map and --world");
	if (o.map.empty() && o.path.empty()) throw core::Error("nothing to evaluate: give --map (with --world) or --path (with --truth)");
	if (o.path.empty() != o.truth.empty()) throw core::Error("--path and --truth go together");
	if (o.map.empty() && !(o.world.empty() && o.perPose.empty() && o.rawlog.empty() && o.poses == 0))
		throw core::Error("--world, --per-pose, --rawlog and --poses score a map: give --map too");
	if (!o.map.empty() && o.world.empty()) throw core::Error("--map needs --world (the true tables)");
	if (!o.walls.empty() && o.map.empty()) throw core::Error("--walls scores a map's walls: give --map and --world too");
	eval::EvalReport report;
	report.options = o.eval;
	if (!o.path.empty())
		report.trajectory = eval::TrajectoryEvaluation::compute(o.path, o.truth, o.eval);  // streamed
	if (o.map.empty())
	{
		std::cout << (o.json ? report.toJson() : report.toText());
		return 0;
	}
	const auto w = world::World::load(o.world);
	bool hasClass = false;
	const auto rows = eval::TableCsv::readMap(o.map, &hasClass);
	const auto estimated = eval::TableCsv::tables(rows);
	report.map = eval::MapEvaluation::compute(w.tables, estimated, o.eval, hasClass);
	report.objectsOnWalls = eval::ObjectsOnWalls::of(w, estimated).size();
	if (!rows.empty() && rows.front().spread) report.spread = eval::SpreadCoverage::of(w.tables, rows, report.map->truthMatch);
	std::vector<world::Wall> estimatedWalls;
	if (!o.walls.empty())
		for (const auto& r : eval::TableCsv::readWalls(o.walls)) estimatedWalls.push_back(r.wall);
	const auto trueWalls = eval::WallEvaluation::trueWalls(w);

	// One streamed pass over the rawlog and the per-pose tables: memory bounded by the
	// world and the map, not the log.
	std::optional<obs::RawlogReader> reader;
	if (!o.rawlog.empty()) reader.emplace(o.rawlog);  // checked end to end first
	const size_t sweeps = reader ? reader->summary().sweepCount : 0;
	std::optional<eval::TableCsv::PerPoseReader> perPose;
	std::optional<eval::PerPoseEvaluation::Accumulator> acc;
	if (!o.perPose.empty())
	{
		if (!reader && o.poses == 0)
			throw core::Error(o.perPose + ": the number of poses is unknown: give --poses N or --rawlog");
		if (reader && o.poses != 0 && o.poses != sweeps)
			throw core::Error(
				o.rawlog + ": holds " + std::to_string(sweeps) + " sweeps, but --poses is " + std::to_string(o.poses));
		perPose.emplace(o.perPose, reader ? sweeps : o.poses);
		acc.emplace(w.tables, o.eval, reader.has_value());
	}
	std::vector<world::Table> tables;
	std::optional<eval::TouchedWalls> touched;  // with --walls and --rawlog
	if (reader)
	{
		const double contactGate = eval::Identifiability::gateFor(reader->summary().maxSigmaR);
		eval::Identifiability::Accumulator ident(w, contactGate);
		if (!o.walls.empty()) touched.emplace(trueWalls, contactGate, o.eval.wall_gate);
		obs::RawlogReader::Sweep s;
		while (reader->next(s))
		{
			ident.add(s);
			if (touched) touched->add(s);
			if (perPose && perPose->next(tables)) acc->add(tables, s.robotPose);
		}
		report.identifiability = ident.result();
	}
	else if (perPose)
		while (perPose->next(tables)) acc->add(tables, mrpt::poses::CPose2D());
	if (acc) report.perPose = acc->result();
	if (!o.walls.empty())
		report.walls = eval::WallEvaluation::compute(
			trueWalls, estimatedWalls, o.eval.wall_gate, o.eval.gate_yaw_deg, touched ? &touched->intervals() : nullptr);
	if (o.calibration) report.calibration = EvalCalibration::ofMap(o.world, o.map, o.candidates, o.eval);
	return print(o, report);
}
}  // namespace

int WhiskerEvalApp::main(int argc, char** argv)
{
	CLI::App app{
		"whisker-eval: score a whisker-map result against the true world. Tables are matched "
		"one-to-one (Hungarian algorithm, least total centre distance, most matches first) "
		"among pairs within the centre and yaw gates (yaw modulo 180 degrees); then precision, "
		"recall, F1, count error (estimated - true), centre RMSE and mean absolute yaw error "
		"over matched tables, and OSPA of the table centres. With --path and --truth, or alone, "
		"it scores an estimated robot path: ATE (RMSE, max; raw and after the best SE(2) "
		"alignment), RPE per metre, final pose error. Definitions: doc/evaluation.md."};
	Options o;
	app.add_option("-w,--world", o.world, "True world .ini (the one simulated; doc/formats.md); needed with --map");
	app.add_option(
		"-m,--map", o.map,
		"Consolidated map CSV written by whisker-map (map_tables.csv: id,x,y,yaw_deg,length,"
		"width,leg_width,texture,existence,contacts,legs[,sd_x,sd_y,sd_yaw_deg][,class]): scored as "
		"written; optional with --path. Objects match only within their class (no class column: all "
		"are tables); with a class column it also reports class accuracy and dimension errors, with "
		"the spread columns how well the reported pose spreads cover the truth");
	app.add_option(
		"--walls", o.walls,
		"Estimated walls CSV (map_walls.csv: x0,y0,x1,y1,thickness,existence), scored as written "
		"against the world's interior walls and arena edges: length recall and precision "
		"(see --wall-gate); needs --map. With --rawlog also the recall of the wall length the "
		"whiskers touched (a contact within 3 sigma_r + 1 cm of a wall marks its centre line "
		"within the wall gate of it)");
	app.add_option(
		"--per-pose", o.perPose,
		"Per-pose MAP tables CSV (per_pose_tables.csv: pose,x,y,yaw_deg,length,width,"
		"leg_width,texture,log_posterior): adds figures averaged over poses; needs --poses or "
		"--rawlog for the number of poses (a pose that found nothing has no row)");
	app.add_option(
		"--rawlog", o.rawlog,
		"The rawlog the map was built from: gives the number of poses and the robot positions "
		"(for the per-pose 'local' figures) and adds the identifiability bound: tables touched "
		"on >= 2 legs (a contact within 3 sigma_r + 1 cm of a leg) and recall on them");
	app.add_option("--poses", o.poses, "Number of poses (sweeps), when --per-pose is given without --rawlog")
		->check(CLI::PositiveNumber);
	app.add_option(
		"--path", o.path,
		"Estimated robot path, one 'timestamp x y yaw_rad' line per sweep (the columns of "
		"whisker-sim's OUT_ground_truth_robot_path.txt; e.g. its OUT_odometry_path.txt)");
	app.add_option(
		"--truth", o.truth,
		"True robot path for --path (OUT_ground_truth_robot_path.txt): same number of lines, "
		"same timestamps (within 1 microsecond)");
	app.add_option(
		   "--rpe-segment", o.eval.rpe_segment_m,
		   "RPE: segments from each pose to the first pose at least this far along the true path, m")
		->check(CLI::PositiveNumber)
		->capture_default_str();
	app.add_flag(
		"--calibration", o.calibration,
		"Existence calibration of --map (and --candidates): its objects binned by reported existence "
		"(10 bins), per bin the count, mean existence and fraction real (matched to a true object), "
		"and the expected calibration error ECE");
	app.add_option(
		"--candidates", o.candidates,
		"map_candidates.csv (same columns as --map), pooled with --map for --calibration only");
	app.add_option(
		"--calibration-runs", o.calibrationRuns,
		"Calibration pooled over many maps: a text file with one 'WORLD MAP [CANDIDATES]' line per run; "
		"prints only the calibration (no --map, --world, --path)");
	app.add_option(
		"--reliability-plot", o.plot,
		"With --calibration or --calibration-runs: write the reliability diagram to this PNG");
	app.add_flag("--json", o.json, "Print one JSON object (fixed key order and format) instead of a table");
	app.add_option(
		   "--gate-distance", o.eval.gate_distance,
		   "Largest centre distance (m) of a matched pair for the paper's 1.0 x 0.6 m table (a "
		   "quarter of its length); scaled by each true object's leg-centre diagonal over the table's")
		->check(CLI::PositiveNumber)
		->capture_default_str();
	app.add_option(
		   "--gate-yaw-deg", o.eval.gate_yaw_deg,
		   "Largest yaw difference (degrees, modulo 180; modulo 90 for a square true object) of a matched pair, in (0, 90]")
		->check(CLI::Range(0.0, 90.0))
		->capture_default_str();
	app.add_option(
		   "--wall-gate", o.eval.wall_gate,
		   "Walls: a point of one wall's centre line counts as covered by another wall whose centre "
		   "line passes within this distance (m) and whose direction is within --gate-yaw-deg")
		->check(CLI::PositiveNumber)
		->capture_default_str();
	app.add_option("--ospa-c", o.eval.ospa_c, "OSPA cut-off c (m): the cost of a missing or extra table")
		->check(CLI::PositiveNumber)
		->capture_default_str();
	app.add_option("--ospa-p", o.eval.ospa_p, "OSPA order p (>= 1)")
		->check(CLI::Range(1.0, 100.0))
		->capture_default_str();
	app.add_option(
		   "--local-radius", o.eval.local_radius,
		   "Per-pose 'local' truth: tables whose centre is within this distance (m) of the "
		   "robot (whisker reach 0.7 m + half a table's diagonal 0.6 m, rounded up)")
		->check(CLI::PositiveNumber)
		->capture_default_str();
	return runApp(app, argc, argv, "whisker-eval", [&] { return run(o); });
}
}  // namespace whiskermap::cli
