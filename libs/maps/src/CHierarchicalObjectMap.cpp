#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapCsv.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using whiskermap::maps::CHierarchicalObjectMap;
using mrpt::maps::CMetricMap;
using mrpt::serialization::CArchive;

IMPLEMENTS_SERIALIZABLE(CHierarchicalObjectMap, CMetricMap, whiskermap::maps)

// Created by name from CMultiMetricMap .ini files: "hierarchicalObjectMap_count=1".
MAP_DEFINITION_REGISTER(
	"hierarchicalObjectMap,whiskermap::maps::CHierarchicalObjectMap",
	whiskermap::maps::CHierarchicalObjectMap)

namespace whiskermap::maps
{
namespace
{
/** MRPT's own keys in <prefix>_creationOpts (read by TMapGenericParams). */
constexpr const char* MRPT_GENERIC_KEYS[] = {
	"enableSaveAs3DObject", "enableObservationLikelihood", "enableObservationInsertion"};

/** Reads a section strictly when present; absent sections keep the defaults. */
template <class F>
void readSection(const mrpt::config::CConfigFileBase& c, const std::string& s, F&& read)
{
	if (!c.sectionExists(s)) return;
	whiskermap::core::IniSection sec(c, s, whiskermap::core::configLabel(c));
	read(sec);
	sec.finish();
}

uint64_t splitmix64(uint64_t x)
{
	x += 0x9E3779B97F4A7C15ull;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
	return x ^ (x >> 31);
}

void write(CArchive& a, const whiskermap::world::Table& t)
{
	a << t.x << t.y << t.yaw << t.length << t.width << t.leg_width << t.texture;
}
void read(CArchive& a, whiskermap::world::Table& t)
{
	a >> t.x >> t.y >> t.yaw >> t.length >> t.width >> t.leg_width >> t.texture;
}
void write(CArchive& a, const whiskermap::obs::Shapelet& s)
{
	a << s.x << s.y << s.normal << s.texture << static_cast<int32_t>(s.whisker);
}
void read(CArchive& a, whiskermap::obs::Shapelet& s)
{
	int32_t w;
	a >> s.x >> s.y >> s.normal >> s.texture >> w;
	s.whisker = w;
}
template <class T>
void writeVec(CArchive& a, const std::vector<T>& v)
{
	a.WriteAs<uint32_t>(v.size());
	for (const auto& x : v) write(a, x);
}
template <class T>
void readVec(CArchive& a, std::vector<T>& v)
{
	v.resize(a.ReadAs<uint32_t>());
	for (auto& x : v) read(a, x);
}
}  // namespace

// ---------------------------------------------------------------- options

void CHierarchicalObjectMap::TInsertionOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	readSection(c, s, [&](core::IniSection& sec) {
		memory_size = static_cast<size_t>(sec.integer("memory_size", memory_size, 1, 1000));
		seed = static_cast<uint64_t>(sec.integer("seed", static_cast<long>(seed), 0, 1L << 53));
		use_sensor_noise = sec.boolean("use_sensor_noise", use_sensor_noise);
		keep_history = sec.boolean("keep_history", keep_history);
		auto& m = consolidation;
		m.merge_distance = sec.number("merge_distance", m.merge_distance, 0, 100);
		m.merge_angle = core::deg2rad(sec.number("merge_angle_deg", core::rad2deg(m.merge_angle), 0, 90));
		m.evidence_margin = sec.number("evidence_margin", m.evidence_margin, 0, 10);
	});
}

void CHierarchicalObjectMap::TInsertionOptions::dumpToTextStream(std::ostream& out) const
{
	out << "memory_size=" << memory_size << "\nseed=" << seed << "\nuse_sensor_noise=" << use_sensor_noise << "\nkeep_history=" << keep_history
		<< "\nmerge_distance=" << consolidation.merge_distance
		<< "\nmerge_angle_deg=" << core::rad2deg(consolidation.merge_angle)
		<< "\nevidence_margin=" << consolidation.evidence_margin << "\n";
}

void CHierarchicalObjectMap::TLikelihoodOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& c, const std::string& s)
{
	readSection(c, s, [&](core::IniSection& sec) {
		sweep.sigma_contact = sec.number("sigma_contact", sweep.sigma_contact, 1e-6, 10);
		sweep.sigma_normal = core::deg2rad(sec.number("sigma_normal_deg", core::rad2deg(sweep.sigma_normal), 0.01, 180));
		sweep.p_unexplained = sec.number("p_unexplained", sweep.p_unexplained, 1e-9, 1);
		sweep.p_miss = sec.number("p_miss", sweep.p_miss, 1e-9, 1);
		min_support = static_cast<uint32_t>(sec.integer("min_support", min_support, 0, 1000000));
	});
}

void CHierarchicalObjectMap::TLikelihoodOptions::dumpToTextStream(std::ostream& out) const
{
	out << "sigma_contact=" << sweep.sigma_contact << "\nsigma_normal_deg=" << core::rad2deg(sweep.sigma_normal)
		<< "\np_unexplained=" << sweep.p_unexplained
		<< "\np_miss=" << sweep.p_miss << "\nmin_support=" << min_support << "\n";
}

CHierarchicalObjectMap::TMapDefinition::TMapDefinition() = default;

void CHierarchicalObjectMap::TMapDefinition::loadFromConfigFile_map_specific(
	const mrpt::config::CConfigFileBase& c, const std::string& prefix)
{
	readSection(c, prefix + "_creationOpts", [&](core::IniSection& sec) {
		for (const char* k : MRPT_GENERIC_KEYS) sec.boolean(k, true);  // MRPT reads these
		auto& r = renderOptions;
		r.table_height = sec.number("table_height", r.table_height, 0.01, 10);
		r.top_thickness = sec.number("top_thickness", r.top_thickness, 0.001, r.table_height);
		r.octomap_resolution = sec.number("octomap_resolution", r.octomap_resolution, 0.001, 1);
	});
	insertionOptions.loadFromConfigFile(c, prefix + "_insertOpts");
	likelihoodOptions.loadFromConfigFile(c, prefix + "_likelihoodOpts");
	readSection(c, prefix + "_model", [&](core::IniSection& sec) {
		modelParams = model::ModelParams::fromIni(sec);
	});
	readSection(c, prefix + "_sampler", [&](core::IniSection& sec) {
		samplerParams = inference::SamplerParams::fromIni(sec);
	});
	// A misspelt section name would otherwise be ignored silently.
	std::vector<std::string> sections;
	c.getAllSections(sections);
	for (const auto& s : sections)
	{
		if (s.rfind(prefix + "_", 0) != 0) continue;
		const std::string suffix = s.substr(prefix.size() + 1);
		if (suffix != "creationOpts" && suffix != "insertOpts" && suffix != "likelihoodOpts" &&
			suffix != "model" && suffix != "sampler")
			throw core::Error(core::configLabel(c) + ": [" + s + "]: unknown section");
	}
}

void CHierarchicalObjectMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const
{
	out << "table_height=" << renderOptions.table_height << "\ntop_thickness=" << renderOptions.top_thickness
		<< "\noctomap_resolution=" << renderOptions.octomap_resolution << "\n";
	insertionOptions.dumpToTextStream(out);
	likelihoodOptions.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CHierarchicalObjectMap::internal_CreateFromMapDefinition(
	const mrpt::maps::TMetricMapInitializer& _def)
{
	const auto& def = dynamic_cast<const TMapDefinition&>(_def);
	auto* m = new CHierarchicalObjectMap();
	m->insertionOptions = def.insertionOptions;
	m->likelihoodOptions = def.likelihoodOptions;
	m->renderOptions = def.renderOptions;
	m->modelParams = def.modelParams;
	m->samplerParams = def.samplerParams;
	return m;
}

// ---------------------------------------------------------------- the map

CHierarchicalObjectMap::CHierarchicalObjectMap() = default;

world::Table CHierarchicalObjectMap::toWorldTable(const model::Table& t) const
{
	return world::Table{
		t.x, t.y, core::angleDiff(t.theta, 0, M_PI), modelParams.table_length, modelParams.table_width,
		t.leg_width, t.texture};
}

std::vector<size_t> CHierarchicalObjectMap::supported() const
{
	// Objects with enough support, best supported first; one overlapping a better supported
	// object is left out (no two tables overlap: the model's factor phi_c, eq. 16). This
	// drops the mirror tables of ambiguous two-leg poses, which share legs with the truth.
	std::vector<size_t> order;
	for (size_t i = 0; i < objects().size(); i++)
		if (objects()[i].support >= likelihoodOptions.min_support) order.push_back(i);
	std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
		return objects()[a].support > objects()[b].support;
	});
	std::vector<size_t> kept;
	std::vector<world::Obstacle> footprints;
	for (size_t i : order)
	{
		const auto foot = objects()[i].table.footprint();
		if (std::any_of(footprints.begin(), footprints.end(), [&](const auto& f) { return f.intersects(foot); }))
			continue;
		kept.push_back(i);
		footprints.push_back(foot);
	}
	return kept;
}

std::vector<world::Table> CHierarchicalObjectMap::supportedTables() const
{
	std::vector<world::Table> tables;
	for (size_t i : supported()) tables.push_back(objects()[i].table);
	return tables;
}

const std::vector<world::Obstacle>& CHierarchicalObjectMap::mappedLegs() const
{
	// Cached: a particle filter scores every particle against the same map.
	auto& c = m_legCache;
	const std::lock_guard<std::mutex> lock(c.mutex);
	if (!c.valid || c.support != likelihoodOptions.min_support)
	{
		c.legs.clear();
		const auto tables = supportedTables();
		for (size_t i = 0; i < tables.size(); i++)
			for (int k = 0; k < 4; k++) c.legs.push_back(tables[i].leg(k, static_cast<int>(i)));
		c.valid = true;
		c.support = likelihoodOptions.min_support;
	}
	return c.legs;
}

bool CHierarchicalObjectMap::isEmpty() const { return m_steps == 0 && objects().empty(); }

void CHierarchicalObjectMap::internal_clear()
{
	m_poses.clear();
	m_consolidator.clear();
	m_shapelets.clear();
	m_memory = inference::ShapeletMemory(insertionOptions.memory_size);
	m_proposed.fill(0);
	m_accepted.fill(0);
	m_lastStep = {};
	m_lastRecord = {};
	m_lastInput = {};
	m_steps = 0;
	m_legCache.invalidate();
}

bool CHierarchicalObjectMap::internal_insertObservation(
	const mrpt::obs::CObservation& o, const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	const auto* sweep = dynamic_cast<const obs::CObservationWhiskerContacts*>(&o);
	if (!sweep) return false;
	auto in = prepareStep(*sweep, robotPose ? mrpt::poses::CPose2D(*robotPose) : mrpt::poses::CPose2D());
	auto result = m_solver.solve(in, samplerParams, m_snapshotTemperature);
	integrateStep(std::move(in), std::move(result));
	return true;
}

TStepInput CHierarchicalObjectMap::prepareStep(
	const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& pose)
{
	if (m_memory.capacity() != insertionOptions.memory_size)
		m_memory = inference::ShapeletMemory(insertionOptions.memory_size);
	TStepInput in;
	in.pose = pose;
	in.shapelets = sweep.toShapelets(pose);
	m_memory.add(in.shapelets);  // working memory: the N most recent shapelets
	in.memory = m_memory.shapelets();
	in.seed = splitmix64(insertionOptions.seed ^ splitmix64(m_steps));
	in.model = modelFor(sweep.noise);
	m_steps++;
	return in;
}

void CHierarchicalObjectMap::integrateStep(TStepInput in, inference::StepResult result)
{
	for (size_t k = 0; k < inference::MOVE_COUNT; k++)
		m_proposed[k] += result.proposed[k], m_accepted[k] += result.accepted[k];
	TPoseRecord rec;
	rec.pose = in.pose;
	rec.logPosterior = result.logPosterior;
	rec.shapelets = static_cast<uint32_t>(in.memory.size());
	for (const auto& t : result.map.tables) rec.tables.push_back(toWorldTable(t));
	m_consolidator.setOptions(insertionOptions.consolidation);
	m_consolidator.addPose(rec.tables, in.shapelets);
	if (insertionOptions.keep_history)
	{
		m_shapelets.insert(m_shapelets.end(), in.shapelets.begin(), in.shapelets.end());
		m_poses.push_back(rec);
	}
	m_lastRecord = std::move(rec);
	m_lastInput = std::move(in);
	m_lastStep = std::move(result);
	m_legCache.invalidate();
}

model::ModelParams CHierarchicalObjectMap::modelFor(const obs::TSensorNoise& noise) const
{
	model::ModelParams m = modelParams;
	if (!insertionOptions.use_sensor_noise) return m;
	if (noise.sigma_r > m.sigma_r)
	{
		m.parent_gate *= noise.sigma_r / m.sigma_r;
		m.sigma_r = noise.sigma_r;
	}
	m.sigma_theta = std::max(m.sigma_theta, noise.sigma_phi);
	m.sigma_tau = std::max(m.sigma_tau, noise.sigma_tau);
	return m;
}

bool CHierarchicalObjectMap::internal_canComputeObservationLikelihood(
	const mrpt::obs::CObservation& o) const
{
	return dynamic_cast<const obs::CObservationWhiskerContacts*>(&o) != nullptr;
}

double CHierarchicalObjectMap::internal_computeObservationLikelihood(
	const mrpt::obs::CObservation& o, const mrpt::poses::CPose3D& takenFrom) const
{
	const auto* sweep = dynamic_cast<const obs::CObservationWhiskerContacts*>(&o);
	if (!sweep) return 0;
	return SweepLikelihood::logLikelihood(
		*sweep, mrpt::poses::CPose2D(takenFrom), mappedLegs(), likelihoodOptions.sweep);
}

void CHierarchicalObjectMap::saveMetricMapRepresentationToFile(const std::string& prefix) const
{
	MapCsv::writeObjects(prefix + "_map_tables.csv", objects());
	MapCsv::writePerPose(prefix + "_per_pose_tables.csv", m_poses);
}

std::string CHierarchicalObjectMap::asString() const
{
	std::ostringstream s;
	const size_t supported = supportedTables().size();
	s << "CHierarchicalObjectMap: " << m_steps << " sweeps inserted, " << m_shapelets.size()
	  << " shapelets kept, " << objects().size() << " objects, " << supported
	  << " in the map as used (support >= " << likelihoodOptions.min_support << ", no overlaps)";
	return s.str();
}

void CHierarchicalObjectMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& scene) const
{
	using namespace mrpt::opengl;
	const double h = renderOptions.table_height;
	for (size_t i : supported())
	{
		const auto& o = objects()[i];
		const auto& t = o.table;
		const float a = static_cast<float>(0.3 + 0.7 * o.existence());
		auto obj = CSetOfObjects::Create();
		obj->setPose(mrpt::poses::CPose3D(t.x, t.y, 0, t.yaw, 0, 0));
		obj->setName("table");
		const double lw = t.leg_width / 2;
		for (int sx : {-1, 1})
			for (int sy : {-1, 1})
			{
				const double cx = sx * t.length / 2, cy = sy * t.width / 2;
				auto leg = CBox::Create(
					mrpt::math::TPoint3D(cx - lw, cy - lw, 0), mrpt::math::TPoint3D(cx + lw, cy + lw, h));
				leg->setColor(0.55f, 0.35f, 0.2f, a);
				leg->setName("leg");
				obj->insert(leg);
			}
		auto top = CBox::Create(
			mrpt::math::TPoint3D(-t.length / 2 - lw, -t.width / 2 - lw, h - renderOptions.top_thickness),
			mrpt::math::TPoint3D(t.length / 2 + lw, t.width / 2 + lw, h));
		top->setColor(0.8f, 0.6f, 0.4f, 0.5f * a);
		top->setName("top");
		obj->insert(top);
		scene.insert(obj);
	}
	if (m_shapelets.empty()) return;
	auto points = CPointCloud::Create();
	auto normals = CSetOfLines::Create();
	for (const auto& s : m_shapelets)
	{
		points->insertPoint(s.x, s.y, 0.05);
		normals->appendLine(s.x, s.y, 0.05, s.x + 0.05 * std::cos(s.normal), s.y + 0.05 * std::sin(s.normal), 0.05);
	}
	points->setColor(0.9f, 0.1f, 0.1f);
	points->setPointSize(3);
	points->setName("shapelets");
	normals->setColor(0.9f, 0.1f, 0.1f);
	normals->setName("normals");
	scene.insert(points);
	scene.insert(normals);
}

mrpt::math::TBoundingBoxf CHierarchicalObjectMap::boundingBox() const
{
	if (m_shapelets.empty() && objects().empty()) return {};
	auto bb = mrpt::math::TBoundingBoxf::PlusMinusInfinity();
	auto add = [&](double x, double y, double z) {
		bb.updateWithPoint(mrpt::math::TPoint3Df(float(x), float(y), float(z)));
	};
	for (const auto& s : m_shapelets) add(s.x, s.y, 0);
	for (const auto& o : objects())
		for (const auto& c : o.table.footprint().corners) add(c.x(), c.y(), renderOptions.table_height);
	return bb;
}

// ---------------------------------------------------------------- serialization

uint8_t CHierarchicalObjectMap::serializeGetVersion() const { return 0; }

void CHierarchicalObjectMap::serializeTo(CArchive& out) const
{
	out << genericMapParams;
	// Options that shape the content (the sampler's settings come from the config).
	const auto& m = modelParams;
	out << m.sigma_r << m.sigma_theta << m.sigma_w << m.sigma_tau << m.c_T << m.c_L << m.c_S
		<< m.alpha_L << m.alpha_S << m.epsilon << m.delta << m.table_length << m.table_width
		<< m.leg_width << m.texture << m.parent_gate;
	const auto& c = insertionOptions.consolidation;
	out.WriteAs<uint32_t>(insertionOptions.memory_size);
	out << insertionOptions.seed << insertionOptions.use_sensor_noise << insertionOptions.keep_history
		<< c.merge_distance << c.merge_angle << c.evidence_margin;
	out << likelihoodOptions.sweep.sigma_contact << likelihoodOptions.sweep.sigma_normal
		<< likelihoodOptions.sweep.p_unexplained
		<< likelihoodOptions.sweep.p_miss << likelihoodOptions.min_support << renderOptions.table_height
		<< renderOptions.top_thickness << renderOptions.octomap_resolution;
	// Content.
	out << m_steps;
	out.WriteAs<uint32_t>(m_poses.size());
	for (const auto& p : m_poses)
	{
		out << p.pose << p.logPosterior << p.shapelets;
		writeVec(out, p.tables);
	}
	out.WriteAs<uint32_t>(objects().size());
	for (const auto& o : objects())
	{
		write(out, o.table);
		out << o.support << o.evidence << o.sum_x << o.sum_y << o.sum_cos2 << o.sum_sin2;
	}
	writeVec(out, m_shapelets);
	writeVec(out, m_memory.shapelets());
	for (size_t k = 0; k < inference::MOVE_COUNT; k++) out << m_proposed[k] << m_accepted[k];
}

void CHierarchicalObjectMap::serializeFrom(CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		{
			internal_clear();
			in >> genericMapParams;
			auto& m = modelParams;
			in >> m.sigma_r >> m.sigma_theta >> m.sigma_w >> m.sigma_tau >> m.c_T >> m.c_L >> m.c_S >>
				m.alpha_L >> m.alpha_S >> m.epsilon >> m.delta >> m.table_length >> m.table_width >>
				m.leg_width >> m.texture >> m.parent_gate;
			auto& c = insertionOptions.consolidation;
			insertionOptions.memory_size = in.ReadAs<uint32_t>();
			in >> insertionOptions.seed >> insertionOptions.use_sensor_noise >> insertionOptions.keep_history >>
				c.merge_distance >> c.merge_angle >> c.evidence_margin;
			in >> likelihoodOptions.sweep.sigma_contact >> likelihoodOptions.sweep.sigma_normal >>
				likelihoodOptions.sweep.p_unexplained >>
				likelihoodOptions.sweep.p_miss >> likelihoodOptions.min_support >>
				renderOptions.table_height >> renderOptions.top_thickness >> renderOptions.octomap_resolution;
			in >> m_steps;
			m_poses.resize(in.ReadAs<uint32_t>());
			for (auto& p : m_poses)
			{
				in >> p.pose >> p.logPosterior >> p.shapelets;
				readVec(in, p.tables);
			}
			std::vector<TMapObject> objs(in.ReadAs<uint32_t>());
			for (auto& o : objs)
			{
				read(in, o.table);
				in >> o.support >> o.evidence >> o.sum_x >> o.sum_y >> o.sum_cos2 >> o.sum_sin2;
			}
			m_consolidator.setObjects(std::move(objs));
			m_consolidator.setOptions(c);
			readVec(in, m_shapelets);
			std::vector<obs::Shapelet> memory;
			readVec(in, memory);
			m_memory = inference::ShapeletMemory(insertionOptions.memory_size);
			m_memory.add(memory);
			for (size_t k = 0; k < inference::MOVE_COUNT; k++) in >> m_proposed[k] >> m_accepted[k];
		}
		break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}
}  // namespace whiskermap::maps
