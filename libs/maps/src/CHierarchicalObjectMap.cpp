#include <mrpt/opengl/CBox.h>
#include <mrpt/opengl/CPointCloud.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapCsv.h>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <sstream>
#include <tuple>

using whiskermap::maps::CHierarchicalObjectMap;
using mrpt::maps::CMetricMap;

IMPLEMENTS_SERIALIZABLE(CHierarchicalObjectMap, CMetricMap, whiskermap::maps)

namespace whiskermap::maps
{
namespace
{
uint64_t splitmix64(uint64_t x)
{
	x += 0x9E3779B97F4A7C15ull;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
	return x ^ (x >> 31);
}
}  // namespace

CHierarchicalObjectMap::CHierarchicalObjectMap() = default;

world::Table CHierarchicalObjectMap::toWorldTable(const model::Table& t) const
{
	return world::Table{
		t.x, t.y, core::angleDiff(t.theta, 0, M_PI), modelParams.lengthOf(t), modelParams.widthOf(t),
		t.leg_width, t.texture, world::ObjectClass(modelParams.nameOf(t.cls))};
}

// ---------------------------------------------------------------- the map as used

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
	return disjoint(order, [&](size_t i) { return objects()[i].table.footprint(); });
}

std::vector<size_t> CHierarchicalObjectMap::disjoint(
	const std::vector<size_t>& order, const std::function<world::Obstacle(size_t)>& footprint)
{
	std::vector<size_t> kept;
	std::vector<world::Obstacle> footprints;
	for (size_t i : order)
	{
		const auto foot = footprint(i);
		if (std::any_of(footprints.begin(), footprints.end(), [&](const auto& f) { return f.intersects(foot); }))
			continue;
		kept.push_back(i);
		footprints.push_back(foot);
	}
	return kept;
}

TMappedObject CHierarchicalObjectMap::mapped(const TMapObject& o) const
{
	return {o.table, o.existence(), o.contacts, static_cast<uint32_t>(std::bitset<8>(o.legMask).count())};
}

TMappedObject CHierarchicalObjectMap::mapped(model::Id t) const
{
	const auto& s = m_lasting.state();
	TMappedObject m{toWorldTable(s.reported(t)), s.existence(t), 0, 0};
	uint8_t corners = 0;  // corners with a leg that explains contacts (two legs may share one)
	for (const model::Id l : s.legsOf(t))
	{
		const uint64_t n = s.contactsExplained(l);
		m.contacts += n;
		if (n > 0 && s.leg(l).corner >= 0) corners = static_cast<uint8_t>(corners | (1u << s.leg(l).corner));
	}
	m.legs = static_cast<uint32_t>(std::bitset<4>(corners).count());
	return m;
}

std::vector<TMappedObject> CHierarchicalObjectMap::lastingObjects(bool inMap, bool spreads) const
{
	const auto& s = m_lasting.state();
	std::vector<bool> inside(static_cast<size_t>(s.tableIdBound()), false);  // in the map, by table id
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		inside[static_cast<size_t>(t)] = s.hasTable(t) && s.existence(t) >= likelihoodOptions.min_existence;
	if (likelihoodOptions.disjoint_tables)
	{
		// Eq. 16 made hard: most contacts first (then the more probable, then the older).
		std::vector<model::Id> ids;  // the tables above min_existence, in id order
		std::vector<TMappedObject> tables;
		for (model::Id t = 0; t < s.tableIdBound(); t++)
			if (inside[static_cast<size_t>(t)])
				ids.push_back(t), tables.push_back(mapped(t)), inside[static_cast<size_t>(t)] = false;
		std::vector<size_t> order(tables.size());
		for (size_t i = 0; i < order.size(); i++) order[i] = i;
		std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
			return std::tie(tables[a].contacts, tables[a].existence) > std::tie(tables[b].contacts, tables[b].existence);
		});
		for (const size_t i : disjoint(order, [&](size_t k) { return tables[k].table.footprint(); }))
			inside[static_cast<size_t>(ids[i])] = true;
	}
	std::vector<TMappedObject> out;
	const model::ModelParams noiseModel = modelFor(m_lastNoise);  // as the last insertion scored its contacts
	for (model::Id t = 0; t < s.tableIdBound(); t++)
	{
		if (!s.hasTable(t) || inside[static_cast<size_t>(t)] != inMap) continue;
		out.push_back(mapped(t));
		if (!spreads) continue;
		if (const auto& chain = s.chainSpread(t); chain.known())  // the posterior chain's (posterior_steps)
		{
			out.back().sd_x = chain.sd_x, out.back().sd_y = chain.sd_y, out.back().sd_yaw = chain.sd_yaw;
			continue;
		}
		const inference::PoseSpread spread = m_lasting.poseSpread(t, noiseModel, out.size() - 1);
		out.back().sd_x = spread.sd_x, out.back().sd_y = spread.sd_y, out.back().sd_yaw = spread.sd_yaw;
	}
	return out;
}

std::vector<TMappedObject> CHierarchicalObjectMap::mapObjects(bool spreads) const
{
	if (lasting()) return lastingObjects(true, spreads);
	std::vector<TMappedObject> out;
	for (const size_t i : supported()) out.push_back(mapped(objects()[i]));
	return out;
}

std::vector<TMappedObject> CHierarchicalObjectMap::candidateObjects(bool spreads) const
{
	if (lasting()) return lastingObjects(false, spreads);
	std::vector<TMappedObject> out;
	auto kept = supported();
	std::sort(kept.begin(), kept.end());
	for (size_t i = 0; i < objects().size(); i++)
		if (!std::binary_search(kept.begin(), kept.end(), i)) out.push_back(mapped(objects()[i]));
	return out;
}

std::vector<model::LastingState::StoredWall> CHierarchicalObjectMap::mapWalls() const
{
	std::vector<model::LastingState::StoredWall> out;
	if (!lasting()) return out;
	for (const auto& w : m_lasting.state().walls())
		if (w.existence >= likelihoodOptions.min_existence) out.push_back(w);
	return out;
}

std::vector<world::Table> CHierarchicalObjectMap::mapTables() const
{
	std::vector<world::Table> tables;
	for (const auto& o : mapObjects()) tables.push_back(o.table);
	return tables;
}

const std::vector<world::Obstacle>& CHierarchicalObjectMap::mappedSolids() const
{
	// Cached: a particle filter scores every particle against the same map.
	auto& c = m_legCache;
	const std::lock_guard<std::mutex> lock(c.mutex);
	const auto& o = likelihoodOptions;
	if (!c.valid || c.support != o.min_support || c.existence != o.min_existence || c.extension != o.wall_extension ||
		c.extensionMin != o.wall_extension_min_length || c.disjoint != o.disjoint_tables)
	{
		c.legs.clear();
		const auto tables = mapTables();
		for (size_t i = 0; i < tables.size(); i++)
			for (int k = 0; k < 4; k++) c.legs.push_back(tables[i].leg(k, static_cast<int>(i)));
		for (const auto& s : mapWalls())
		{
			const auto& w = s.wall;
			const double grow = w.length() >= o.wall_extension_min_length ? o.wall_extension : 0;
			c.legs.push_back(world::Obstacle::rectangle(
				{(w.x0 + w.x1) / 2, (w.y0 + w.y1) / 2}, std::atan2(w.y1 - w.y0, w.x1 - w.x0), w.length() / 2 + grow,
				w.thickness / 2, w.texture));
		}
		c.valid = true;
		c.support = o.min_support;
		c.existence = o.min_existence;
		c.extension = o.wall_extension;
		c.extensionMin = o.wall_extension_min_length;
		c.disjoint = o.disjoint_tables;
	}
	return c.legs;
}

bool CHierarchicalObjectMap::isEmpty() const
{
	return m_steps == 0 && objects().empty() && m_lasting.state().legCount() == 0 &&
		   m_lasting.state().contactCount() == 0;
}

// ---------------------------------------------------------------- insertion

void CHierarchicalObjectMap::internal_clear()
{
	m_poses.clear();
	m_consolidator.clear();
	m_lasting.clear();
	m_lastLasting = {};
	m_sweptGrid.clear(insertionOptions.swept_cell);
	m_shapelets.clear();
	m_memory = inference::ShapeletMemory(insertionOptions.memory_size);
	m_sweptMemory = inference::SweptMemory(insertionOptions.memory_size);
	m_proposed.fill(0);
	m_moveTypes.clear();
	m_accepted.fill(0);
	m_lastStep = {};
	m_lastRecord = {};
	m_lastInput = {};
	m_steps = 0;
	m_lastNoise = {};
	m_legCache.invalidate();
}

bool CHierarchicalObjectMap::internal_insertObservation(
	const mrpt::obs::CObservation& o, const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	const auto* sweep = dynamic_cast<const obs::CObservationWhiskerContacts*>(&o);
	if (!sweep) return false;
	const mrpt::poses::CPose2D pose = robotPose ? mrpt::poses::CPose2D(*robotPose) : mrpt::poses::CPose2D();
	if (lasting())
	{
		insertLasting(*sweep, pose);
		return true;
	}
	auto in = prepareStep(*sweep, pose);
	auto result = m_solver.solve(in, samplerParams, m_snapshotTemperature);
	integrateStep(std::move(in), std::move(result));
	return true;
}

void CHierarchicalObjectMap::recordSwept(
	const mrpt::poses::CPose2D& pose, const std::vector<obs::Shapelet>& shapelets,
	const std::vector<obs::SweptSector>& sectors)
{
	if (m_sweptGrid.empty() && m_sweptGrid.cellSize() != insertionOptions.swept_cell)
		m_sweptGrid.clear(insertionOptions.swept_cell);
	std::vector<std::array<double, 2>> contacts;
	for (const auto& s : shapelets) contacts.push_back({s.x, s.y});
	m_sweptGrid.addSweep(pose.x(), pose.y(), sectors, contacts);
}

void CHierarchicalObjectMap::insertLasting(const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& pose)
{
	TStepInput in;
	in.pose = pose;
	in.shapelets = sweep.toShapelets(pose);
	if (insertionOptions.record_swept) recordSwept(pose, in.shapelets, sweep.toSweptSectors(pose));
	in.seed = splitmix64(insertionOptions.seed ^ splitmix64(m_steps));
	in.model = modelFor(sweep.noise);
	m_lastNoise = sweep.noise;
	m_steps++;
	m_lasting.setOptions(insertionOptions.lasting);
	m_lastLasting = m_lasting.insert(in.shapelets, in.model, samplerParams, in.seed, &m_sweptGrid);
	inference::addMoveCounts(m_proposed, m_accepted, m_moveTypes, m_lastLasting);
	if (insertionOptions.keep_history)
	{
		m_shapelets.insert(m_shapelets.end(), in.shapelets.begin(), in.shapelets.end());
		m_poses.push_back(TPoseRecord{pose, {}, 0, static_cast<uint32_t>(in.shapelets.size())});
	}
	m_lastRecord = TPoseRecord{pose, {}, 0, static_cast<uint32_t>(in.shapelets.size())};
	m_lastInput = std::move(in);
	if (m_lastLasting.changed) m_legCache.invalidate();
}

void CHierarchicalObjectMap::annealPending()
{
	if (!lasting() || m_lasting.pendingSweeps() == 0) return;
	m_lasting.setOptions(insertionOptions.lasting);
	const uint64_t seed = splitmix64(insertionOptions.seed ^ splitmix64(m_steps));  // the next sweep's
	m_lastLasting = m_lasting.annealPending(modelFor(m_lastNoise), samplerParams, seed, &m_sweptGrid);
	inference::addMoveCounts(m_proposed, m_accepted, m_moveTypes, m_lastLasting);
	m_legCache.invalidate();
}

TStepInput CHierarchicalObjectMap::prepareStep(
	const obs::CObservationWhiskerContacts& sweep, const mrpt::poses::CPose2D& pose)
{
	if (m_memory.capacity() != insertionOptions.memory_size)
		m_memory = inference::ShapeletMemory(insertionOptions.memory_size);
	TStepInput in;
	in.pose = pose;
	in.shapelets = sweep.toShapelets(pose);
	const auto sectors = sweep.toSweptSectors(pose);
	if (insertionOptions.record_swept) recordSwept(pose, in.shapelets, sectors);
	m_memory.add(in.shapelets);  // working memory: the N most recent shapelets
	in.memory = m_memory.shapelets();
	in.seed = splitmix64(insertionOptions.seed ^ splitmix64(m_steps));
	in.model = modelFor(sweep.noise);
	if (in.model.free_space)  // and the free space its sweeps swept (eq. 21)
	{
		if (m_sweptMemory.capacity() != insertionOptions.memory_size)
			m_sweptMemory = inference::SweptMemory(insertionOptions.memory_size);
		m_sweptMemory.add(in.shapelets.size(), sectors);
		in.swept = m_sweptMemory.sectors();
	}
	m_steps++;
	return in;
}

void CHierarchicalObjectMap::integrateStep(TStepInput in, inference::StepResult result)
{
	inference::addMoveCounts(m_proposed, m_accepted, m_moveTypes, result);
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
		// The per-pose mode keeps the paper's single sigma_r (eqs. 6-7); the lasting map raises
		// only the readings' noise (eq. 7): legs stand at their corners however noisy the
		// sensor (doc/model.md, "Two noises").
		if (!lasting()) m.sigma_corner *= noise.sigma_r / m.sigma_r;
		m.sigma_r = noise.sigma_r;
	}
	m.sigma_theta = std::max(m.sigma_theta, noise.sigma_phi);
	m.sigma_tau = std::max(m.sigma_tau, noise.sigma_tau);
	return m;
}

// ---------------------------------------------------------------- likelihood

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
		*sweep, mrpt::poses::CPose2D(takenFrom), mappedSolids(), likelihoodOptions.sweep, &m_sweptGrid);
}

// ---------------------------------------------------------------- files, text, 3-D

void CHierarchicalObjectMap::saveMetricMapRepresentationToFile(const std::string& prefix) const
{
	if (lasting() && m_lasting.pendingSweeps() > 0)
	{
		// Stock tools (rbpf-slam's final map) save without calling annealPending(): the files
		// hold the map as annealPending() would leave it, annealed on a copy; this map keeps
		// its sweeps pending, so what it does next is unchanged.
		CHierarchicalObjectMap annealed(*this);
		annealed.annealPending();
		annealed.saveMetricMapRepresentationToFile(prefix);
		return;
	}
	const bool withClass = !modelParams.classes.empty();
	MapCsv::writeObjects(prefix + "_map_tables.csv", mapObjects(lasting()), withClass, lasting());
	MapCsv::writeObjects(prefix + "_map_candidates.csv", candidateObjects(lasting()), withClass, lasting());
	if (!lasting()) MapCsv::writePerPose(prefix + "_per_pose_tables.csv", m_poses);
}

std::string CHierarchicalObjectMap::asString() const
{
	std::ostringstream s;
	const size_t mapped = mapObjects().size();
	s << "CHierarchicalObjectMap (" << (lasting() ? "lasting" : "per-pose") << "): " << m_steps << " sweeps inserted, ";
	if (lasting())
	{
		const auto& st = m_lasting.state();
		s << st.tableCount() << " tables (" << mapped << " with existence >= " << likelihoodOptions.min_existence
		  << "), " << st.legCount() << " legs, " << st.contactCount() << " explicit contacts";
	}
	else
		s << objects().size() << " objects, " << mapped << " in the map (support >= " << likelihoodOptions.min_support
		  << ", no overlaps)";
	return s.str();
}

void CHierarchicalObjectMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& scene) const
{
	using namespace mrpt::opengl;
	const double h = renderOptions.table_height;
	for (const auto& o : mapObjects())
	{
		const auto& t = o.table;
		const float a = static_cast<float>(0.3 + 0.7 * o.existence);
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
	const auto objs = mapObjects();
	if (m_shapelets.empty() && objs.empty()) return {};
	auto bb = mrpt::math::TBoundingBoxf::PlusMinusInfinity();
	auto add = [&](double x, double y, double z) {
		bb.updateWithPoint(mrpt::math::TPoint3Df(float(x), float(y), float(z)));
	};
	for (const auto& s : m_shapelets) add(s.x, s.y, 0);
	for (const auto& o : objs)
		for (const auto& c : o.table.footprint().corners) add(c.x(), c.y(), renderOptions.table_height);
	return bb;
}
}  // namespace whiskermap::maps
