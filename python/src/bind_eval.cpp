// The evaluation against ground truth: whisker-eval's figures (doc/evaluation.md).
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <whiskermap/eval/EvalReport.h>
#include <whiskermap/eval/ObjectsOnWalls.h>
#include <whiskermap/eval/TableCsv.h>

#include "Bindings.h"
#include "Records.h"

namespace whiskermap::python
{
namespace
{
using namespace whiskermap::eval;
using Contents = obs::RawlogReader::Contents;

std::vector<std::vector<world::Table>> perPoseTables(const std::vector<py::object>& arrays)
{
	std::vector<std::vector<world::Table>> out;
	for (const auto& a : arrays) out.push_back(fromArray<world::Table>(a, "per_pose[" + std::to_string(out.size()) + "]"));
	return out;
}

/** whisker-eval's report: the map, and optionally identifiability (rawlog) and per-pose
 *  figures (per-pose tables, with the rawlog's robot poses when given). */
EvalReport evaluate(
	const world::World& w, const py::handle& tables, const std::optional<std::vector<py::object>>& perPose,
	const Contents* rawlog, const EvalOptions& options)
{
	options.validate();
	EvalReport report;
	report.options = options;
	const auto estimated = fromArray<world::Table>(tables, "tables");
	report.map = MapEvaluation::compute(w.tables, estimated, options);
	report.objectsOnWalls = ObjectsOnWalls::of(w, estimated).size();
	std::vector<mrpt::poses::CPose2D> robotPoses;
	if (rawlog)
	{
		report.identifiability = Identifiability::of(w, rawlog->sweeps, Identifiability::defaultGate(rawlog->sweeps));
		for (const auto& s : rawlog->sweeps) robotPoses.push_back(s.robotPose);
	}
	if (perPose)
	{
		if (rawlog && perPose->size() != rawlog->sweeps.size())
			throw core::Error(
				"per_pose: holds " + std::to_string(perPose->size()) + " poses, but the rawlog holds " +
				std::to_string(rawlog->sweeps.size()) + " sweeps");
		report.perPose = PerPoseEvaluation::compute(w.tables, perPoseTables(*perPose), robotPoses, options);
	}
	return report;
}
}  // namespace

void bindEval(py::module_& m)
{
	py::class_<EvalOptions>(m, "EvalOptions", "Gates and parameters of the evaluation (eval::EvalOptions; doc/evaluation.md).")
		.def(py::init([](double gd, double gy, double c, double p, double lr) { return EvalOptions{gd, gy, c, p, lr}; }),
			 py::arg("gate_distance") = EvalOptions{}.gate_distance, py::arg("gate_yaw_deg") = EvalOptions{}.gate_yaw_deg,
			 py::arg("ospa_c") = EvalOptions{}.ospa_c, py::arg("ospa_p") = EvalOptions{}.ospa_p,
			 py::arg("local_radius") = EvalOptions{}.local_radius)
		.def_readwrite("gate_distance", &EvalOptions::gate_distance)
		.def_readwrite("gate_yaw_deg", &EvalOptions::gate_yaw_deg)
		.def_readwrite("ospa_c", &EvalOptions::ospa_c)
		.def_readwrite("ospa_p", &EvalOptions::ospa_p)
		.def_readwrite("local_radius", &EvalOptions::local_radius)
		.def("validate", &EvalOptions::validate);

	py::class_<Figures>(m, "Figures", "Scores of an estimated set of tables against the truth (rmse_m, yaw_err_deg: NaN when nothing matched).")
		.def_readonly("precision", &Figures::precision)
		.def_readonly("recall", &Figures::recall)
		.def_readonly("f1", &Figures::f1)
		.def_readonly("count_error", &Figures::count_error)
		.def_readonly("rmse_m", &Figures::rmse_m)
		.def_readonly("rmse_aligned_m", &Figures::rmse_aligned_m)
		.def_readonly("yaw_err_deg", &Figures::yaw_err_deg)
		.def_readonly("ospa", &Figures::ospa);

	py::class_<MapEvaluation>(m, "MapEvaluation", "Tables matched one-to-one to the truth (Hungarian, within the gates) and the figures.")
		.def_static("compute", [](const py::handle& truth, const py::handle& estimated, const EvalOptions& o) {
			return MapEvaluation::compute(fromArray<world::Table>(truth, "truth"), fromArray<world::Table>(estimated, "estimated"), o);
		}, py::arg("truth"), py::arg("estimated"), py::arg("options") = EvalOptions{})
		.def_readonly("estimated", &MapEvaluation::estimated)
		.def_readonly("truth", &MapEvaluation::truth)
		.def_readonly("matched", &MapEvaluation::matched)
		.def_readonly("figures", &MapEvaluation::figures)
		.def_readonly("truth_match", &MapEvaluation::truthMatch, "per true table, the index of its estimated match or -1");

	py::class_<PerPoseEvaluation>(m, "PerPoseEvaluation", "Per-pose MAP tables scored pose by pose and averaged.")
		.def_static("compute", [](const py::handle& truth, const std::vector<py::object>& perPose, const py::object& poses,
								  const EvalOptions& o) {
			return PerPoseEvaluation::compute(fromArray<world::Table>(truth, "truth"), perPoseTables(perPose),
											  poses.is_none() ? std::vector<mrpt::poses::CPose2D>{} : posesFromArray(poses), o);
		}, py::arg("truth"), py::arg("per_pose"), py::arg("robot_poses") = py::none(), py::arg("options") = EvalOptions{})
		.def_readonly("poses", &PerPoseEvaluation::poses)
		.def_readonly("all", &PerPoseEvaluation::all)
		.def_readonly("local", &PerPoseEvaluation::local);

	py::class_<Identifiability>(m, "Identifiability", "Tables touched on at least two legs: what any mapper could find.")
		.def_static("of", [](const world::World& w, const Contents& rawlog, std::optional<double> gate) {
			return Identifiability::of(w, rawlog.sweeps, gate ? *gate : Identifiability::defaultGate(rawlog.sweeps));
		}, py::arg("world"), py::arg("rawlog"), py::arg("gate") = py::none())
		.def_readonly("tables", &Identifiability::tables)
		.def_readonly("gate", &Identifiability::gate)
		.def("recall", &Identifiability::recall, py::arg("evaluation"));

	py::class_<EvalReport>(m, "EvalReport", "Everything whisker-eval reports (eval::EvalReport).")
		.def_readonly("options", &EvalReport::options)
		.def_readonly("map", &EvalReport::map)
		.def_readonly("identifiability", &EvalReport::identifiability)
		.def_readonly("per_pose", &EvalReport::perPose)
		.def_readonly("objects_on_walls", &EvalReport::objectsOnWalls, "the map's objects standing on a true wall")
		.def("to_json", &EvalReport::toJson, "whisker-eval --json's text")
		.def("to_text", &EvalReport::toText, "whisker-eval's table")
		.def("to_dict", [](const EvalReport& r) { return py::module_::import("json").attr("loads")(r.toJson()); },
			 "to_json() as a dict (undefined figures: None)");

	m.def("evaluate", [](const world::World& w, const py::handle& tables, const std::optional<std::vector<py::object>>& perPose,
						 const Contents* rawlog, const EvalOptions& o) { return evaluate(w, tables, perPose, rawlog, o); },
		  py::arg("world"), py::arg("tables"), py::arg("per_pose") = py::none(), py::arg("rawlog") = py::none(),
		  py::arg("options") = EvalOptions{},
		  "whisker-eval in a call: tables (a map's map_tables() or map_objects()) scored against the world; "
		  "per_pose (a table array per sweep) adds the per-pose figures; rawlog (read_rawlog) adds the "
		  "identifiability bound and the robot positions of the 'local' per-pose figures.");
	m.def("read_map_csv", [](const Path& path) { return toArray(TableCsv::tables(TableCsv::readMap(path.string()))); },
		  py::arg("path"), "The tables of a map_tables.csv, read strictly as whisker-eval does (TABLE_DTYPE).");
	m.def("read_per_pose_csv", [](const Path& path, size_t poses) {
		std::vector<py::array> out;
		for (const auto& t : TableCsv::readPerPose(path.string(), poses)) out.push_back(toArray(t));
		return out;
	}, py::arg("path"), py::arg("poses"), "A per_pose_tables.csv: a TABLE_DTYPE array per pose, poses 0 .. poses-1.");
}
}  // namespace whiskermap::python
