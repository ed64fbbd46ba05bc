// The map: a CMultiMetricMap built from a config file, holding a CHierarchicalObjectMap.
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/serialization/CArchive.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <whiskermap/core/ConfigPaths.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/maps/MapCsv.h>

#include <mutex>
#include <optional>
#include <shared_mutex>

#include "Bindings.h"
#include "Records.h"

namespace whiskermap::python
{
namespace
{
using maps::CHierarchicalObjectMap;
using TMode = CHierarchicalObjectMap::TInsertionOptions::TMode;
using Obs = obs::CObservationWhiskerContacts;

TMode parseMode(const std::string& mode)
{
	if (mode == "lasting") return TMode::Lasting;
	if (mode == "per_pose") return TMode::PerPose;
	throw core::Error("mode '" + mode + "': expected 'lasting' or 'per_pose'");
}

/** The multimap and its hierarchical map. Calls run without the GIL (other Python threads go
 *  on) under a lock: insertions alone, reads together. */
class Map
{
   public:
	Map(const std::optional<Path>& config, const std::optional<std::string>& mode, const std::optional<uint64_t> seed)
		: m_config(config ? config->string() : core::ConfigPaths::find("whisker-map.ini")),
		  m_multimap(std::make_unique<mrpt::maps::CMultiMetricMap>(maps::MapConfig::load(m_config)))
	{
		attach();
		if (mode) m_map->insertionOptions.mode = parseMode(*mode);
		if (seed) m_map->insertionOptions.seed = *seed;
	}
	Map(const Map& o) : m_config(o.m_config)
	{
		const std::shared_lock lock(o.m_mutex);
		m_multimap = std::make_unique<mrpt::maps::CMultiMetricMap>(*o.m_multimap);
		attach();
	}

	/** f(map) without the GIL, alone. */
	template <class F>
	auto write(F&& f)
	{
		py::gil_scoped_release nogil;
		const std::unique_lock lock(m_mutex);
		return f(*m_multimap, *m_map);
	}
	/** f(map) without the GIL, with other readers. */
	template <class F>
	auto read(F&& f) const
	{
		py::gil_scoped_release nogil;
		const std::shared_lock lock(m_mutex);
		return f(static_cast<const CHierarchicalObjectMap&>(*m_map));
	}

	const std::string& config() const { return m_config; }

   private:
	void attach()
	{
		m_map = m_multimap->mapByClass<CHierarchicalObjectMap>().get();
		if (!m_map) throw core::Error(m_config + ": no hierarchicalObjectMap was created (is libwhiskermap-maps loaded?)");
	}
	std::string m_config;
	std::unique_ptr<mrpt::maps::CMultiMetricMap> m_multimap;
	CHierarchicalObjectMap* m_map = nullptr;
	mutable std::shared_mutex m_mutex;
};

py::bytes toBytes(const Map& map)
{
	const std::string data = map.read([](const CHierarchicalObjectMap& m) {
		mrpt::io::CMemoryStream buf;
		auto archive = mrpt::serialization::archiveFrom(buf);
		archive << m;
		return std::string(static_cast<const char*>(buf.getRawBufferData()), buf.getTotalBytesCount());
	});
	return py::bytes(data);
}

std::unique_ptr<Map> fromBytes(const py::bytes& bytes, const std::optional<Path>& config)
{
	auto map = std::make_unique<Map>(config, std::nullopt, std::nullopt);
	const std::string data = bytes;
	map->write([&](mrpt::maps::CMultiMetricMap&, CHierarchicalObjectMap& m) {
		mrpt::io::CMemoryStream buf;
		buf.assignMemoryNotOwn(data.data(), data.size());
		auto archive = mrpt::serialization::archiveFrom(buf);
		archive.ReadObject(&m);
		if (buf.getPosition() != data.size())
			throw core::Error(
				"map bytes: " + std::to_string(data.size() - buf.getPosition()) + " bytes left after the map");
		return 0;
	});
	return map;
}

}  // namespace

void bindMaps(py::module_& m)
{
	m.attr("OBJECT_DTYPE") = dtypeOf<maps::TMappedObject>();

	py::class_<maps::TPoseRecord>(m, "PoseRecord", "What one sweep concluded in the per-pose mode: its MAP tables (eq. 18).")
		.def(py::init([](const Pose& pose, const py::handle& tables, double logPosterior, uint32_t shapelets) {
			return maps::TPoseRecord{toPose2D(pose), fromArray<world::Table>(tables, "tables"), logPosterior, shapelets};
		}), py::arg("pose"), py::arg("tables"), py::arg("log_posterior") = 0.0, py::arg("shapelets") = 0)
		.def_property_readonly("pose", [](const maps::TPoseRecord& r) { return fromPose2D(r.pose); }, "robot pose of the sweep")
		.def_property_readonly("tables", [](const maps::TPoseRecord& r) { return toArray(r.tables); }, "MAP tables, TABLE_DTYPE")
		.def_readonly("log_posterior", &maps::TPoseRecord::logPosterior, "log joint (eq. 14) of the MAP blackboard")
		.def_readonly("shapelets", &maps::TPoseRecord::shapelets, "shapelets in working memory");

	py::class_<Map>(m, "Map",
					"A map of tables from whisker sweeps: a CMultiMetricMap built from a config file (default: the "
					"shipped config/whisker-map.ini) holding a CHierarchicalObjectMap (doc/map-plugin.md). mode: "
					"'lasting' (one state fusing every contact) or 'per_pose' (the paper's steps, merged by votes); "
					"seed: the base seed. Same config, mode, seed and sweeps: the same map as whisker-map.")
		.def(py::init<const std::optional<Path>&, const std::optional<std::string>&, std::optional<uint64_t>>(),
			 py::arg("config") = py::none(), py::arg("mode") = py::none(), py::arg("seed") = py::none())
		.def_property_readonly("config", &Map::config, "the config file it was built from")
		.def_property("mode",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.lasting(); }) ? "lasting" : "per_pose"; },
			[](Map& mp, const std::string& s) {
				const auto mode = parseMode(s);
				mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.insertionOptions.mode = mode; });
			})
		.def_property("seed",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.insertionOptions.seed; }); },
			[](Map& mp, uint64_t v) { mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.insertionOptions.seed = v; }); })
		.def_property("keep_history",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.insertionOptions.keep_history; }); },
			[](Map& mp, bool v) { mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.insertionOptions.keep_history = v; }); },
			"keep every per-pose record and shapelet (pose_records(), shapelets())")
		.def_property("min_existence",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.likelihoodOptions.min_existence; }); },
			[](Map& mp, double v) { mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.likelihoodOptions.min_existence = v; }); },
			"lasting mode: the map holds the tables at least this probable")
		.def_property("min_support",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.likelihoodOptions.min_support; }); },
			[](Map& mp, uint32_t v) { mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.likelihoodOptions.min_support = v; }); },
			"per-pose mode: objects found at fewer poses are left out")
		.def_property("disjoint_tables",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.likelihoodOptions.disjoint_tables; }); },
			[](Map& mp, bool v) { mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.likelihoodOptions.disjoint_tables = v; }); },
			"lasting mode: no two mapped tables overlap (eq. 16 made hard; likelihoodOpts disjoint_tables)")
		.def_property("batch_sweeps",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.insertionOptions.lasting.batch_sweeps; }); },
			[](Map& mp, uint32_t v) {
				if (v < 1 || v > 1000) throw py::value_error("batch_sweeps must be in [1, 1000], not " + std::to_string(v));
				mp.write([&](auto&, CHierarchicalObjectMap& x) { return x.insertionOptions.lasting.batch_sweeps = v; });
			},
			"lasting mode: sweeps with contacts annealed together (insertOpts batch_sweeps); see anneal_pending()")
		.def_property_readonly("pending_sweeps",
			[](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.lastingMap().pendingSweeps(); }); },
			"lasting mode: sweeps inserted whose contacts are not annealed yet (batch_sweeps > 1)")
		.def("anneal_pending", [](Map& mp) { mp.write([](auto&, CHierarchicalObjectMap& x) { return x.annealPending(), 0; }); },
			 "lasting mode: anneals the pending sweeps' contacts now (call it before reading a finished map)")
		.def_property_readonly("steps", [](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.steps(); }); },
							   "sweeps inserted")
		.def("insert", [](Map& mp, const Obs& sweep, const Pose& pose) {
			const auto p = toPose3D(pose);
			return mp.write([&](mrpt::maps::CMultiMetricMap& mm, auto&) { return mm.insertObservation(sweep, p); });
		}, py::arg("sweep"), py::arg("pose"), "Inserts a sweep taken at this robot pose into every map of the multimap.")
		.def("likelihood", [](const Map& mp, const Obs& sweep, const Pose& pose) {
			const auto p = toPose3D(pose);
			return mp.read([&](const CHierarchicalObjectMap& x) { return x.computeObservationLikelihood(sweep, p); });
		}, py::arg("sweep"), py::arg("pose"),
			"log-likelihood of the sweep if taken at this pose (computeObservationLikelihood: SweepLikelihood)")
		.def("likelihoods", [](const Map& mp, const Obs& sweep, const py::handle& poses) {
			const auto ps = posesFromArray(poses);
			const auto v = mp.read([&](const CHierarchicalObjectMap& x) {
				std::vector<double> out;
				for (const auto& p : ps) out.push_back(x.computeObservationLikelihood(sweep, mrpt::poses::CPose3D(p)));
				return out;
			});
			return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
		}, py::arg("sweep"), py::arg("poses"), "likelihood() at each row (x, y, yaw) of an (n, 3) array: one weight per particle")
		.def("map_objects", [](const Map& mp, bool spreads) { return toArray(mp.read([&](const CHierarchicalObjectMap& x) { return x.mapObjects(spreads); })); },
			 py::arg("spreads") = false,
			 "The map (map_tables.csv): OBJECT_DTYPE (x, y, yaw, length, width, leg_width, texture, existence, contacts, legs, "
			 "sd_x, sd_y, sd_yaw). spreads (lasting mode): each object's pose spread (a short chain each); else NaN.")
		.def("candidate_objects", [](const Map& mp, bool spreads) { return toArray(mp.read([&](const CHierarchicalObjectMap& x) { return x.candidateObjects(spreads); })); },
			 py::arg("spreads") = false, "Everything else the map considered (map_candidates.csv), OBJECT_DTYPE.")
		.def("map_tables", [](const Map& mp) { return toArray(mp.read([](const CHierarchicalObjectMap& x) { return x.mapTables(); })); },
			 "The tables of map_objects(), TABLE_DTYPE.")
		.def("pose_records", [](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.poseRecords(); }); },
			 "Per inserted sweep (with keep_history): its PoseRecord; MAP tables in the per-pose mode.")
		.def("shapelets", [](const Map& mp) { return toArray(mp.read([](const CHierarchicalObjectMap& x) { return x.shapelets(); })); },
			 "Every contact inserted, world frame (with keep_history), SHAPELET_DTYPE.")
		.def("is_empty", [](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.isEmpty(); }); })
		.def("describe", [](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.asString(); }); })
		.def("__str__", [](const Map& mp) { return mp.read([](const CHierarchicalObjectMap& x) { return x.asString(); }); })
		.def("save", [](const Map& mp, const Path& prefix) {
			mp.read([&](const CHierarchicalObjectMap& x) { return x.saveMetricMapRepresentationToFile(prefix.string()), 0; });
		}, py::arg("prefix"),
			"Writes <prefix>_map_tables.csv, <prefix>_map_candidates.csv and, per-pose mode, <prefix>_per_pose_tables.csv.")
		.def("to_bytes", &toBytes, "The CHierarchicalObjectMap, MRPT-serialized (its class, version and content).")
		.def_static("from_bytes", &fromBytes, py::arg("data"), py::arg("config") = py::none(),
					"A map built from config (its sampler settings) with the content of to_bytes() data.")
		.def("copy", [](const Map& mp) { return std::make_unique<Map>(mp); }, "A deep copy (e.g. for a resampled particle).")
		.def("__copy__", [](const Map& mp) { return std::make_unique<Map>(mp); })
		.def("__deepcopy__", [](const Map& mp, const py::dict&) { return std::make_unique<Map>(mp); }, py::arg("memo"));

	m.def("write_objects_csv", [](const Path& path, const py::handle& objects, bool spreads) {
		maps::MapCsv::writeObjects(path.string(), fromArray<maps::TMappedObject>(objects, "objects"), false, spreads);
	}, py::arg("path"), py::arg("objects"), py::arg("spreads") = false,
		  "map_tables.csv as whisker-map writes it (maps::MapCsv::writeObjects), from an OBJECT_DTYPE array; spreads: "
		  "with the sd_x, sd_y, sd_yaw_deg columns (the lasting map's; every object must have them).");
	m.def("write_per_pose_csv", [](const Path& path, const std::vector<maps::TPoseRecord>& records) {
		maps::MapCsv::writePerPose(path.string(), records);
	}, py::arg("path"), py::arg("records"),
		  "per_pose_tables.csv as whisker-map writes it (maps::MapCsv::writePerPose), from PoseRecords.");
}
}  // namespace whiskermap::python
