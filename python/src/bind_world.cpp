// Ground truth and simulation: worlds, robots, the whisker simulator, trajectories.
#include <mrpt/system/datetime.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>
#include <whiskermap/world/World.h>

#include "Bindings.h"
#include "Records.h"

namespace whiskermap::python
{
void bindWorld(py::module_& m)
{
	using world::World, world::Robot, world::WhiskerSimulator, world::Trajectory;
	m.attr("TABLE_DTYPE") = dtypeOf<world::Table>();
	m.attr("TRUTH_DTYPE") = dtypeOf<WhiskerSimulator::Truth>();

	m.def("config_path", &core::ConfigPaths::find, py::arg("relative"),
		  "A shipped config file, e.g. 'worlds/paper_arena.ini': $WHISKERMAP_CONFIG_DIR, the source "
		  "tree's config/, then the installed share/whiskermap/config (core::ConfigPaths::find).");

	py::class_<World>(m, "World", "An arena walled on its edges and its tables: ground truth (world::World).")
		.def_static("load", [](const Path& p) { return World::load(p.string()); }, py::arg("path"), "Reads and validates a world .ini (doc/formats.md).")
		.def("save", [](const World& w, const Path& p, const std::string& comment) { w.save(p.string(), comment); },
			 py::arg("path"), py::arg("comment") = "")
		.def("tiled", &World::tiled, py::arg("nx"), py::arg("ny"), "This world repeated nx by ny times.")
		.def_readonly("x_min", &World::x_min)
		.def_readonly("x_max", &World::x_max)
		.def_readonly("y_min", &World::y_min)
		.def_readonly("y_max", &World::y_max)
		.def_readonly("wall_texture", &World::wall_texture)
		.def_property_readonly("tables", [](const World& w) { return toArray(w.tables); }, "TABLE_DTYPE array");

	py::class_<Robot>(m, "Robot", "A whiskered robot's geometry: body radius and whisker mountings (world::Robot).")
		.def_static("load", [](const Path& arg) { return Robot::load(core::ConfigPaths::resolve(arg.string(), "robots")); },
					py::arg("name_or_path"), "A robot .ini, or a shipped robot name such as 'scratchbot'.")
		.def_readonly("radius", &Robot::radius)
		.def_property_readonly("sensor_pose", [](const Robot& r) { return fromPose3D(r.sensorPose); })
		.def_property_readonly("whiskers", [](const Robot& r) { return toArray(r.whiskers); }, "WHISKER_DTYPE mountings")
		.def("blank_sweep", [](const Robot& r, const obs::TSensorNoise& n, double t) {
			return r.blankSweep(n, mrpt::Clock::fromDouble(t));
		}, py::arg("noise"), py::arg("timestamp") = 0.0, "A sweep in which no whisker touched anything.");

	py::class_<WhiskerSimulator>(m, "Simulator",
								 "Simulates sweeps in a world: exact 2-D contact geometry, then Gaussian reading "
								 "noise (world::WhiskerSimulator). Same seed and calls, same sweeps.")
		.def(py::init<World, Robot, obs::TSensorNoise, uint64_t>(), py::arg("world"), py::arg("robot"),
			 py::arg("noise"), py::arg("seed") = 1)
		.def("pose_is_free", [](const WhiskerSimulator& s, const Pose& p) { return s.poseIsFree(toPose2D(p)); },
			 py::arg("pose"), "False when the robot body would overlap a leg or stand outside the walls.")
		.def("sense", [](WhiskerSimulator& s, const Pose& p, double t) {
			return s.sense(toPose2D(p), mrpt::Clock::fromDouble(t));
		}, py::arg("pose"), py::arg("timestamp") = 0.0, "One sweep at this robot pose.")
		.def("sense_with_truth", [](WhiskerSimulator& s, const Pose& p, double t) {
			std::vector<WhiskerSimulator::Truth> truth;
			auto sweep = s.sense(toPose2D(p), mrpt::Clock::fromDouble(t), &truth);
			return py::make_tuple(sweep, toArray(truth));
		}, py::arg("pose"), py::arg("timestamp") = 0.0,
			 "(sweep, truth): what each whisker really touched (TRUTH_DTYPE: table, leg, wall).")
		.def_property_readonly("world", &WhiskerSimulator::world)
		.def_property_readonly("robot", &WhiskerSimulator::robot);

	m.def("paper_grid", [](const World& w, int n) { return posesToArray(Trajectory::paperGrid(w, n)); },
		  py::arg("world"), py::arg("n") = 10,
		  "The paper's poses: n x n cell centres row by row, each at headings 0, 90, 180, 270 degrees.");
	m.def("paper_grid", [](const World& w, int nx, int ny) { return posesToArray(Trajectory::paperGrid(w, nx, ny)); },
		  py::arg("world"), py::arg("nx"), py::arg("ny"));
	m.def("read_path_file", [](const Path& path) { return posesToArray(Trajectory::readPathFile(path.string())); },
		  py::arg("path"), "A path file: one 'x y yaw_deg' per line (doc/formats.md); (n, 3) array, yaw in radians.");
	m.def("write_path_file", [](const Path& path, const py::handle& poses, const std::string& comment) {
		Trajectory::writePathFile(path.string(), posesFromArray(poses), comment);
	}, py::arg("path"), py::arg("poses"), py::arg("comment") = "");
}
}  // namespace whiskermap::python
