// Sweeps (CObservationWhiskerContacts), sensor noise, rawlogs in and out.
#include <mrpt/system/datetime.h>
#include <pybind11/functional.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/RawlogWriter.h>

#include <optional>
#include <sstream>

#include "Bindings.h"
#include "Records.h"

namespace whiskermap::python
{
namespace
{
using Obs = obs::CObservationWhiskerContacts;
using Contents = obs::RawlogReader::Contents;

std::shared_ptr<Obs> makeSweep(
	const py::handle& whiskers, const obs::TSensorNoise& noise, const Pose& sensorPose, double timestamp,
	const std::string& label)
{
	auto o = std::make_shared<Obs>();
	o->whiskers = fromArray<obs::TWhisker>(whiskers, "whiskers");
	o->noise = noise;
	o->sensorPose = toPose3D(sensorPose);
	o->timestamp = mrpt::Clock::fromDouble(timestamp);
	o->sensorLabel = label;
	o->validate();
	return o;
}

py::tuple sweepAt(const Contents& c, py::ssize_t i)
{
	const auto n = static_cast<py::ssize_t>(c.sweeps.size());
	if (i < 0) i += n;
	if (i < 0 || i >= n) throw py::index_error("sweep index out of range");
	const auto& s = c.sweeps[static_cast<size_t>(i)];
	return py::make_tuple(fromPose2D(s.robotPose), s.obs);
}

/** world::RawlogWriter with an explicit end: closed (files renamed into place) or dropped
 *  (temporary files removed). */
class Writer
{
   public:
	Writer(const Path& path, const std::string& format, bool groundTruth) : m_path(path.string())
	{
		if (format != "obs" && format != "action-sf")
			throw core::Error("format '" + format + "': expected 'obs' or 'action-sf'");
		m_w.emplace(
			m_path,
			format == "obs" ? world::RawlogWriter::Format::Observations
							: world::RawlogWriter::Format::ActionSensoryFrame,
			groundTruth ? world::RawlogWriter::GroundTruth::Write : world::RawlogWriter::GroundTruth::None);
	}
	void write(const Pose& pose, const Obs& sweep) { get().write(toPose2D(pose), sweep); }
	void close()
	{
		get().close();
		m_w.reset();
	}
	void drop() { m_w.reset(); }
	bool open() const { return m_w.has_value(); }

   private:
	world::RawlogWriter& get()
	{
		if (!m_w) throw core::Error(m_path + ": the rawlog writer is closed");
		return *m_w;
	}
	std::string m_path;
	std::optional<world::RawlogWriter> m_w;
};
}  // namespace

void bindObs(py::module_& m)
{
	py::class_<obs::TSensorNoise>(m, "Noise", "Reading noise std-devs of a sweep (obs::TSensorNoise, eqs. 1-3).")
		.def(py::init([](double r, double phi, double tau) { return obs::TSensorNoise{r, phi, tau}; }),
			 py::arg("sigma_r") = 0.0, py::arg("sigma_phi") = 0.0, py::arg("sigma_tau") = 0.0)
		.def_readwrite("sigma_r", &obs::TSensorNoise::sigma_r, "radial distance, metres")
		.def_readwrite("sigma_phi", &obs::TSensorNoise::sigma_phi, "surface-normal angle, radians")
		.def_readwrite("sigma_tau", &obs::TSensorNoise::sigma_tau, "texture, in [0, 1]")
		.def_static("load", [](const Path& p) { return world::NoisePreset::load(p.string()); }, py::arg("name_or_path"),
					"A noise .ini, or a shipped preset name: noiseless, default, very-noisy (NoisePreset).")
		.def("__repr__", [](const obs::TSensorNoise& n) {
			std::ostringstream s;
			s << "Noise(sigma_r=" << n.sigma_r << ", sigma_phi=" << n.sigma_phi << ", sigma_tau=" << n.sigma_tau << ")";
			return s.str();
		});

	m.attr("WHISKER_DTYPE") = dtypeOf<obs::TWhisker>();
	m.attr("SHAPELET_DTYPE") = dtypeOf<obs::Shapelet>();

	py::class_<Obs, std::shared_ptr<Obs>>(
		m, "Sweep",
		"One whisking sweep (obs::CObservationWhiskerContacts, an MRPT observation), immutable. "
		"whiskers: a structured array, one row per whisker (WHISKER_DTYPE: mount_x, mount_y, "
		"sweep_start, sweep_end, length, touched, angle, r, normal, texture; sensor frame, metres, "
		"radians); validated on construction (WhiskermapError naming the whisker and field).")
		.def(py::init(&makeSweep), py::arg("whiskers"), py::arg("noise") = obs::TSensorNoise{},
			 py::arg("sensor_pose") = Pose{0, 0, 0}, py::arg("timestamp") = 0.0, py::arg("label") = "WHISKERS")
		.def_property_readonly("whiskers", [](const Obs& o) { return toArray(o.whiskers); })
		.def_property_readonly("noise", [](const Obs& o) { return o.noise; })
		.def_property_readonly("sensor_pose", [](const Obs& o) { return fromPose3D(o.sensorPose); },
							   "whisker-array frame on the robot, (x, y, yaw)")
		.def_property_readonly("timestamp", [](const Obs& o) { return mrpt::Clock::toDouble(o.timestamp); },
							   "seconds (UNIX time)")
		.def_property_readonly("label", [](const Obs& o) { return o.sensorLabel; })
		.def("contact_count", &Obs::contactCount, "whiskers that touched something")
		.def("shapelets", [](const Obs& o, const Pose& robotPose) { return toArray(o.toShapelets(toPose2D(robotPose))); },
			 py::arg("robot_pose"), "World-frame contacts for the robot at this pose (SHAPELET_DTYPE).")
		.def("describe", [](const Obs& o) {
			std::ostringstream s;
			o.getDescriptionAsText(s);
			return s.str();
		})
		.def("__len__", [](const Obs& o) { return o.whiskers.size(); });

	py::class_<Contents>(m, "Rawlog",
						 "The whisker sweeps of a rawlog with the robot pose of each (obs::RawlogReader); "
						 "rawlog[i] is (pose, sweep).")
		.def_property_readonly("sweeps", [](const Contents& c) {
			std::vector<std::shared_ptr<Obs>> v;
			for (const auto& s : c.sweeps) v.push_back(s.obs);
			return v;
		})
		.def_property_readonly("poses", [](const Contents& c) {
			std::vector<mrpt::poses::CPose2D> p;
			for (const auto& s : c.sweeps) p.push_back(s.robotPose);
			return posesToArray(p);
		}, "(n, 3) array: x, y, yaw of each sweep")
		.def_readonly("objects", &Contents::objects, "top-level objects read")
		.def_readonly("action_sensory_frame", &Contents::actionSensoryFrameFormat,
					  "True for the actions/sensory-frames layout")
		.def("__len__", [](const Contents& c) { return c.sweeps.size(); })
		.def("__getitem__", &sweepAt);

	m.def("read_rawlog", [](const Path& path) {
		py::gil_scoped_release nogil;
		return obs::RawlogReader::read(path.string());
	}, py::arg("path"), "Reads a rawlog (either MRPT layout) into memory (obs::RawlogReader::read).");

	m.def("for_each_sweep", [](const Path& path, const std::function<void(Pose, std::shared_ptr<Obs>)>& fn) {
		py::gil_scoped_release nogil;
		return obs::RawlogReader::forEach(path.string(), [&](const obs::RawlogReader::Sweep& s) {
			py::gil_scoped_acquire gil;
			fn(fromPose2D(s.robotPose), s.obs);
		}).sweepCount;
	}, py::arg("path"), py::arg("fn"),
		  "Streams a rawlog: fn(pose, sweep) per sweep, one in memory at a time; the file is verified "
		  "whole first. Returns the number of sweeps.");

	py::class_<Writer>(m, "RawlogWriter",
					   "Writes sweeps with their robot poses as a rawlog (world::RawlogWriter): format 'obs' "
					   "(odometry + observations) or 'action-sf' (actions + sensory frames, for rbpf-slam); "
					   "ground_truth writes <name>_ground_truth_robot_path.txt beside it. Nothing appears until "
					   "close(); as a context manager it closes on success and removes everything on an exception.")
		.def(py::init<const Path&, const std::string&, bool>(), py::arg("path"), py::arg("format") = "obs",
			 py::arg("ground_truth") = true)
		.def("write", &Writer::write, py::arg("pose"), py::arg("sweep"))
		.def("close", &Writer::close)
		.def_property_readonly("is_open", &Writer::open)
		.def("__enter__", [](Writer& w) -> Writer& { return w; }, py::return_value_policy::reference)
		.def("__exit__", [](Writer& w, const py::object& type, const py::object&, const py::object&) {
			if (type.is_none() && w.open())
				w.close();
			else
				w.drop();
		});
}
}  // namespace whiskermap::python
