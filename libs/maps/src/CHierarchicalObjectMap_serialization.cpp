// CHierarchicalObjectMap: versioned MRPT serialization (doc/map-plugin.md). Version 0 (no
// lasting map) still loads, as a per-pose map; version 1 (no shaft directions) as contacts
// without a known shaft; versions before 3 with the lasting tables reported at their own poses;
// versions before 4 without walls (walls = false); versions before 5 with an empty swept grid
// (the likelihood then knows no free space); versions before 6 with sigma_corner = sigma_r and
// no revisions; versions before 7 without the counts per move type; versions before 8 without
// size moves (every lasting table at its class's size); versions before 9 without the last
// insertion's sensor noise; versions before 10 without the walls' end-cap costs (0); versions
// before 11 with every class's legs nominal; versions before 12 with every sweep annealed at
// once; versions before 13 without the posterior chain's pose spreads (none); versions before
// 14 without Manhattan walls and with walls as mapped in the likelihood; versions before 15
// recording every sweep in the swept grid; versions before 16 merging only overlapping legs;
// versions before 17 with eq. 16 soft in the lasting map (disjoint_tables = false).
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/model/ObjectCatalogue.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

using mrpt::serialization::CArchive;

namespace whiskermap::maps
{
namespace
{
void write(CArchive& a, const world::Table& t) { a << t.x << t.y << t.yaw << t.length << t.width << t.leg_width << t.texture; }
void read(CArchive& a, world::Table& t, uint8_t) { a >> t.x >> t.y >> t.yaw >> t.length >> t.width >> t.leg_width >> t.texture; }
void write(CArchive& a, const obs::Shapelet& s)
{
	a << s.x << s.y << s.normal << s.texture << static_cast<int32_t>(s.whisker) << s.shaft_x << s.shaft_y;
}
void read(CArchive& a, obs::Shapelet& s, uint8_t version)
{
	int32_t w;
	a >> s.x >> s.y >> s.normal >> s.texture >> w;
	s.whisker = w;
	if (version >= 2) a >> s.shaft_x >> s.shaft_y;
}
template <class T>
void writeVec(CArchive& a, const std::vector<T>& v)
{
	a.WriteAs<uint32_t>(v.size());
	for (const auto& x : v) write(a, x);
}
/** Reads the `n` items a count announced, one by one: MRPT reads a field cut short by the
 *  stream's end without throwing, so a truncated or corrupt count can be huge; growing item
 *  by item, the stream's end (which throws) comes long before memory runs out. */
template <class T, class F>
void readEach(std::vector<T>& v, uint32_t n, F&& readOne)
{
	v.clear();
	v.reserve(std::min<uint32_t>(n, 1024));
	for (uint32_t i = 0; i < n; i++) readOne(v.emplace_back());
}
template <class T>
void readVec(CArchive& a, std::vector<T>& v, uint8_t version)
{
	readEach(v, a.ReadAs<uint32_t>(), [&](T& x) { read(a, x, version); });
}

/** The lasting state, ids renumbered densely in ascending order. */
void writeLasting(CArchive& out, const model::LastingState& s)
{
	std::vector<model::Id> tableIndex(static_cast<size_t>(s.tableIdBound()), model::NONE);
	std::vector<model::Id> legIndex(static_cast<size_t>(s.legIdBound()), model::NONE);
	out.WriteAs<uint32_t>(s.tableCount());
	model::Id n = 0;
	for (model::Id t = 0; t < s.tableIdBound(); t++)
	{
		if (!s.hasTable(t)) continue;
		const auto& tb = s.table(t);
		out << tb.x << tb.y << tb.theta << tb.leg_width << tb.texture << s.existence(t);
		out << s.reported(t).x << s.reported(t).y << s.reported(t).theta;  // version 3
		tableIndex[static_cast<size_t>(t)] = n++;
	}
	out.WriteAs<uint32_t>(s.legCount());
	n = 0;
	for (model::Id l = 0; l < s.legIdBound(); l++)
	{
		if (!s.hasLeg(l)) continue;
		const auto& g = s.leg(l);
		const int32_t parent = g.parent == model::NONE ? -1 : tableIndex[static_cast<size_t>(g.parent)];
		out << g.x << g.y << g.theta << g.wx << g.wy << g.texture << parent;
		for (const double v : s.evidence(l).stats()) out << v;
		out << s.evidence(l).count();
		legIndex[static_cast<size_t>(l)] = n++;
	}
	out.WriteAs<uint32_t>(s.contactCount());
	for (model::Id c = 0; c < s.contactIdBound(); c++)
	{
		if (!s.hasContact(c)) continue;
		const auto& k = s.contact(c);
		write(out, k.shapelet);
		out << static_cast<int32_t>(k.leg == model::NONE ? -1 : legIndex[static_cast<size_t>(k.leg)]) << k.seq;
	}
	out << s.nextSeq();
}

/** The parts of a lasting state as read; restored once the classes (version 3) are known. */
struct LastingParts
{
	std::vector<model::Table> tables;
	std::vector<double> existence;
	std::vector<model::Table> reported;  // versions before 3: none (the tables' own poses)
	std::vector<model::Leg> legs;
	std::vector<model::LegEvidence> evidence;
	std::vector<model::LastingState::Contact> contacts;
	uint64_t seq = 0;
};

void readLasting(CArchive& in, LastingParts& parts, uint8_t version)
{
	parts.existence.clear();
	readEach(parts.tables, in.ReadAs<uint32_t>(), [&](model::Table& t) {
		in >> t.x >> t.y >> t.theta >> t.leg_width >> t.texture >> parts.existence.emplace_back();
		if (version < 3) return;
		auto& r = parts.reported.emplace_back(t);
		in >> r.x >> r.y >> r.theta;
	});
	parts.evidence.clear();
	readEach(parts.legs, in.ReadAs<uint32_t>(), [&](model::Leg& g) {
		int32_t parent;
		in >> g.x >> g.y >> g.theta >> g.wx >> g.wy >> g.texture >> parent;
		if (parent < -1 || parent >= static_cast<int32_t>(parts.tables.size()))
			THROW_EXCEPTION("CHierarchicalObjectMap: corrupt lasting state (leg parent out of range)");
		g.parent = parent;
		std::array<double, model::LegEvidence::STATS> stats{};
		const size_t known = version >= 3 ? stats.size() : version == 2 ? 34 : 33;
		for (size_t k = 0; k < known; k++) in >> stats[k];
		uint32_t count;
		in >> count;
		parts.evidence.push_back(model::LegEvidence::fromStats(stats, count, known));
	});
	readEach(parts.contacts, in.ReadAs<uint32_t>(), [&](model::LastingState::Contact& k) {
		read(in, k.shapelet, version);
		int32_t leg;
		in >> leg >> k.seq;
		if (leg < -1 || leg >= static_cast<int32_t>(parts.legs.size()))
			THROW_EXCEPTION("CHierarchicalObjectMap: corrupt lasting state (contact leg out of range)");
		k.leg = leg;
	});
	in >> parts.seq;
}

void writeClasses(CArchive& out, const model::ModelParams& m, const model::LastingState& s)
{
	out.WriteAs<uint32_t>(static_cast<uint32_t>(m.classes.size()));
	for (const auto& c : m.classes)
		out << c.name << c.label << c.length << c.width << c.leg_width << c.texture << c.size_sigma << c.prior;
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		if (s.hasTable(t)) out.WriteAs<int32_t>(s.table(t).cls);
}

/** Version 7: the proposal and acceptance counts per move type; each name at most 255 bytes
 *  (a length byte), at most MAX_MOVE_TYPES of them. */
constexpr uint32_t MAX_MOVE_TYPES = 64;
void writeMoveTypes(CArchive& out, const std::vector<inference::MoveTally>& tallies)
{
	out.WriteAs<uint32_t>(static_cast<uint32_t>(tallies.size()));
	for (const auto& t : tallies)
	{
		const auto n = static_cast<uint8_t>(std::min<size_t>(t.name.size(), 255));
		out.WriteAs<uint8_t>(n);
		out.WriteBuffer(t.name.data(), n);
		out << t.proposed << t.accepted;
	}
}

void readMoveTypes(CArchive& in, std::vector<inference::MoveTally>& tallies)
{
	const auto n = in.ReadAs<uint32_t>();
	if (n > MAX_MOVE_TYPES) THROW_EXCEPTION("CHierarchicalObjectMap: corrupt stream (too many move types)");
	tallies.resize(n);
	for (auto& t : tallies)
	{
		t.name.resize(in.ReadAs<uint8_t>());
		in.ReadBuffer(t.name.data(), t.name.size());  // throws at the end of the stream
		in >> t.proposed >> t.accepted;
		if (t.accepted > t.proposed) THROW_EXCEPTION("CHierarchicalObjectMap: corrupt stream (more acceptances than proposals)");
	}
}

/** Version 4: the wall keys of the model and the lasting map's walls. */
void writeWalls(CArchive& out, const model::ModelParams& m, const model::LastingState& s)
{
	out << m.walls << m.c_W << m.wall_length_scale << m.wall_thickness;
	out.WriteAs<uint32_t>(s.walls().size());
	for (const auto& w : s.walls())
	{
		out << w.wall.x0 << w.wall.y0 << w.wall.x1 << w.wall.y1 << w.wall.thickness << w.wall.texture << w.existence;
		for (const double v : w.evidence.stats()) out << v;
		out << w.evidence.count();
	}
}

void readWalls(CArchive& in, model::ModelParams& m, std::vector<model::LastingState::StoredWall>& walls, uint8_t version)
{
	in >> m.walls >> m.c_W >> m.wall_length_scale >> m.wall_thickness;
	const auto n = in.ReadAs<uint32_t>();
	if (n > (1u << 24)) THROW_EXCEPTION("CHierarchicalObjectMap: corrupt stream (too many walls)");
	readEach(walls, n, [&](model::LastingState::StoredWall& w) {
		in >> w.wall.x0 >> w.wall.y0 >> w.wall.x1 >> w.wall.y1 >> w.wall.thickness >> w.wall.texture >> w.existence;
		std::array<double, model::WallEvidence::STATS> v{};
		const size_t known = version >= 10 ? v.size() : model::WallEvidence::STATS_BEFORE_CAPS;
		for (size_t i = 0; i < known; i++) in >> v[i];
		if (!std::isfinite(v.back()) || v.back() < 0)
			THROW_EXCEPTION("CHierarchicalObjectMap: corrupt lasting state (wall end-cap cost not a number >= 0)");
		w.evidence = model::WallEvidence::fromStats(v, in.ReadAs<uint32_t>());
	});
}

/** Version 3: the catalogue and the class of each lasting table (older streams: class 0). */
void readClasses(CArchive& in, model::ModelParams& m, LastingParts& parts)
{
	const auto n = in.ReadAs<uint32_t>();
	if (n > model::ObjectCatalogue::MAX_CLASSES)
		THROW_EXCEPTION("CHierarchicalObjectMap: corrupt stream (too many object classes)");
	m.classes.resize(n);
	for (auto& c : m.classes) in >> c.name >> c.label >> c.length >> c.width >> c.leg_width >> c.texture >> c.size_sigma >> c.prior;
	for (auto& t : parts.tables)
	{
		t.cls = in.ReadAs<int32_t>();
		if (t.cls < 0 || t.cls >= m.classCount())
			THROW_EXCEPTION("CHierarchicalObjectMap: corrupt lasting state (table class out of range)");
	}
}
/** Version 4: the swept grid, its explored cells only. */
void writeSwept(CArchive& out, const model::SweptGrid& g)
{
	out << g.cellSize();
	const auto cells = g.cells();
	out.WriteAs<uint32_t>(static_cast<uint32_t>(cells.size()));
	for (const auto& c : cells) out << c.ix << c.iy << c.cell.passes << c.cell.touches;
}

void readSwept(CArchive& in, model::SweptGrid& g)
{
	double cell;
	in >> cell;
	if (!(cell > 0)) THROW_EXCEPTION("CHierarchicalObjectMap: corrupt swept grid (cell size <= 0)");
	g.clear(cell);
	const uint32_t n = in.ReadAs<uint32_t>();
	for (uint32_t k = 0; k < n; k++)
	{
		model::SweptGrid::IndexedCell c;
		in >> c.ix >> c.iy >> c.cell.passes >> c.cell.touches;
		if (std::abs(static_cast<int64_t>(c.ix)) > (1 << 24) || std::abs(static_cast<int64_t>(c.iy)) > (1 << 24))
			THROW_EXCEPTION("CHierarchicalObjectMap: corrupt swept grid (cell index out of range)");
		g.set(c.ix, c.iy, c.cell);
	}
}

/** Version 8: size moves, and each lasting table's size offsets and its reported table's. */
void writeSizes(CArchive& out, const model::ModelParams& m, const model::LastingState& s)
{
	out << m.size_moves;
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		if (s.hasTable(t))
			out << s.table(t).d_length << s.table(t).d_width << s.reported(t).d_length << s.reported(t).d_width;
}

void readSizes(CArchive& in, model::ModelParams& m, LastingParts& parts)
{
	in >> m.size_moves;
	if (m.size_moves && m.classes.empty())
		THROW_EXCEPTION("CHierarchicalObjectMap: corrupt model (size moves without an object catalogue)");
	for (size_t i = 0; i < parts.tables.size(); i++)
	{
		auto& t = parts.tables[i];
		in >> t.d_length >> t.d_width;
		double rl, rw;
		in >> rl >> rw;
		if (i < parts.reported.size()) parts.reported[i].d_length = rl, parts.reported[i].d_width = rw;
		for (const double v : {t.d_length, t.d_width, rl, rw})
			if (!std::isfinite(v) || std::abs(v) > 100)
				THROW_EXCEPTION("CHierarchicalObjectMap: corrupt lasting state (table size offset not finite or above 100 m)");
	}
}

/** Version 11: each class's spreads of leg width and texture (eq. 26). */
void writeLegSpreads(CArchive& out, const model::ModelParams& m)
{
	for (const auto& c : m.classes) out << c.leg_width_sigma << c.texture_sigma;
}

void readLegSpreads(CArchive& in, model::ModelParams& m)
{
	for (auto& c : m.classes)
	{
		in >> c.leg_width_sigma >> c.texture_sigma;
		for (const double v : {c.leg_width_sigma, c.texture_sigma})
			if (!(v >= 0 && v <= 1))
				THROW_EXCEPTION("CHierarchicalObjectMap: corrupt object class (leg width or texture spread not a number in [0, 1])");
	}
}

/** Per live table, in id order (writeLasting's): its posterior chain's pose spread. */
void writeChainSpreads(CArchive& out, const model::LastingState& s)
{
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		if (s.hasTable(t)) out << s.chainSpread(t).sd_x << s.chainSpread(t).sd_y << s.chainSpread(t).sd_yaw;
}

/** After restore(), which numbers the tables densely in stream order. */
void readChainSpreads(CArchive& in, model::LastingState& s)
{
	for (model::Id t = 0; t < s.tableIdBound(); t++)
	{
		model::LastingState::ChainSpread c;
		in >> c.sd_x >> c.sd_y >> c.sd_yaw;
		const bool none = c.sd_x == -1 && c.sd_y == -1 && c.sd_yaw == -1;
		for (const double v : {c.sd_x, c.sd_y, c.sd_yaw})
			if (!none && !(v >= 0 && v <= 1e3))
				THROW_EXCEPTION("CHierarchicalObjectMap: corrupt pose spread (not -1 for none, nor a number in [0, 1000])");
		s.setChainSpread(t, c);
	}
}
}  // namespace

uint8_t CHierarchicalObjectMap::serializeGetVersion() const { return 17; }

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
		<< likelihoodOptions.sweep.p_unexplained << likelihoodOptions.sweep.p_miss << likelihoodOptions.min_support
		<< renderOptions.table_height << renderOptions.top_thickness << renderOptions.octomap_resolution;
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
	// Version 1: the lasting mode.
	const auto& l = insertionOptions.lasting;
	out.WriteAs<uint8_t>(static_cast<uint8_t>(insertionOptions.mode));
	out << l.visit_radius << l.contacts_per_leg << l.unexplained_per_spot << likelihoodOptions.min_existence;
	for (const auto& o : objects()) out << o.contacts << o.legMask;
	writeLasting(out, m_lasting.state());
	// Version 2: shaft noise (shapelets carry their shafts above) and free space.
	out << m.shaft_noise << m.sigma_across << m.free_space << m.free_space_p_miss;
	// Version 3: the lasting tables' reported poses (in writeLasting) and whether they are
	// rigid fits; the object catalogue and the lasting tables' classes.
	out << l.rigid_pose;
	writeClasses(out, m, m_lasting.state());
	// Version 4: walls.
	writeWalls(out, m, m_lasting.state());
	// Version 5: the swept grid and the likelihood's free-space options.
	const auto& sw = likelihoodOptions.sweep;
	out << insertionOptions.swept_cell << sw.use_swept_grid << sw.cell_prior << sw.cell_prior_sweeps << sw.p_unexplored;
	writeSwept(out, m_sweptGrid);
	// Version 6: eq. 6's own position noise, the lasting map's revisions.
	out << m.sigma_corner << l.noisy_revisions << m_lasting.reviseSeq();
	// Version 7: the counts per move type.
	writeMoveTypes(out, m_moveTypes);
	// Version 8: size moves and the lasting tables' sizes.
	writeSizes(out, m, m_lasting.state());
	// Version 9: the sensor noise of the last lasting insertion (the pose spreads' model).
	out << m_lastNoise.sigma_r << m_lastNoise.sigma_phi << m_lastNoise.sigma_tau;
	// Version 11: the classes' leg width and texture spreads.
	writeLegSpreads(out, m);
	// Version 12: sweeps annealed together, and the sweeps pending (inserted, not annealed).
	out << l.batch_sweeps << m_lasting.pendingSweeps() << m_lasting.pendingFrom();
	// Version 13: the lasting tables' pose spreads from the posterior chain (-1: none).
	writeChainSpreads(out, m_lasting.state());
	// Version 14: Manhattan walls, and the likelihood's wall extension.
	out << m.manhattan_walls << m.wall_axis << likelihoodOptions.wall_extension << likelihoodOptions.wall_extension_min_length;
	// Version 15: whether sweeps are recorded in the swept grid.
	out << insertionOptions.record_swept;
	// Version 16: legs merged within a gap.
	out << l.leg_merge_gap;
	// Version 17: no two mapped tables overlapping.
	out << likelihoodOptions.disjoint_tables;
}

void CHierarchicalObjectMap::serializeFrom(CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		case 1:
		case 2:
		case 3:
		case 4:
		case 5:
		case 6:
		case 7:
		case 8:
		case 9:
		case 10:
		case 11:
		case 12:
		case 13:
		case 14:
		case 15:
		case 16:
		case 17:
		{
			internal_clear();
			in >> genericMapParams;
			auto& m = modelParams;
			in >> m.sigma_r >> m.sigma_theta >> m.sigma_w >> m.sigma_tau >> m.c_T >> m.c_L >> m.c_S >>
				m.alpha_L >> m.alpha_S >> m.epsilon >> m.delta >> m.table_length >> m.table_width >>
				m.leg_width >> m.texture >> m.parent_gate;
			auto& c = insertionOptions.consolidation;
			insertionOptions.memory_size = in.ReadAs<uint32_t>();
			if (insertionOptions.memory_size < 1 || insertionOptions.memory_size > 1000)
				THROW_EXCEPTION("CHierarchicalObjectMap: corrupt options (memory_size not in [1, 1000])");
			in >> insertionOptions.seed >> insertionOptions.use_sensor_noise >> insertionOptions.keep_history >>
				c.merge_distance >> c.merge_angle >> c.evidence_margin;
			in >> likelihoodOptions.sweep.sigma_contact >> likelihoodOptions.sweep.sigma_normal >>
				likelihoodOptions.sweep.p_unexplained >> likelihoodOptions.sweep.p_miss >> likelihoodOptions.min_support >>
				renderOptions.table_height >> renderOptions.top_thickness >> renderOptions.octomap_resolution;
			in >> m_steps;
			readEach(m_poses, in.ReadAs<uint32_t>(), [&](TPoseRecord& p) {
				in >> p.pose >> p.logPosterior >> p.shapelets;
				readVec(in, p.tables, version);
			});
			std::vector<TMapObject> objs;
			readEach(objs, in.ReadAs<uint32_t>(), [&](TMapObject& o) {
				read(in, o.table, version);
				in >> o.support >> o.evidence >> o.sum_x >> o.sum_y >> o.sum_cos2 >> o.sum_sin2;
			});
			readVec(in, m_shapelets, version);
			std::vector<obs::Shapelet> memory;
			readVec(in, memory, version);
			m_memory = inference::ShapeletMemory(insertionOptions.memory_size);
			m_memory.add(memory);
			for (size_t k = 0; k < inference::MOVE_COUNT; k++) in >> m_proposed[k] >> m_accepted[k];
			insertionOptions.mode = TInsertionOptions::TMode::PerPose;  // version 0 knew no other
			LastingParts lasting;
			if (version >= 1)
			{
				const uint8_t mode = in.ReadAs<uint8_t>();
				if (mode > 1) THROW_EXCEPTION("CHierarchicalObjectMap: unknown mode in stream");
				insertionOptions.mode = static_cast<TInsertionOptions::TMode>(mode);
				auto& l = insertionOptions.lasting;
				in >> l.visit_radius >> l.contacts_per_leg >> l.unexplained_per_spot >> likelihoodOptions.min_existence;
				for (auto& o : objs) in >> o.contacts >> o.legMask;
				readLasting(in, lasting, version);
			}
			const model::ModelParams defaults;  // versions 0 and 1 knew only the paper's eqs. 7 and 14
			m.shaft_noise = defaults.shaft_noise, m.sigma_across = defaults.sigma_across;
			m.free_space = defaults.free_space, m.free_space_p_miss = defaults.free_space_p_miss;
			if (version >= 2) in >> m.shaft_noise >> m.sigma_across >> m.free_space >> m.free_space_p_miss;
			insertionOptions.lasting.rigid_pose = false;  // versions before 3 reported the tables' own poses
			if (version >= 3) in >> insertionOptions.lasting.rigid_pose;
			m.classes.clear();  // versions 0 to 2: one class, the known table
			if (version >= 3) readClasses(in, m, lasting);
			const model::ModelParams noWalls;  // versions before 4: no walls
			m.walls = noWalls.walls, m.c_W = noWalls.c_W, m.wall_length_scale = noWalls.wall_length_scale;
			m.wall_thickness = noWalls.wall_thickness;
			std::vector<model::LastingState::StoredWall> walls;
			if (version >= 4) readWalls(in, m, walls, version);
			if (version >= 5)
			{
				auto& sw = likelihoodOptions.sweep;
				in >> insertionOptions.swept_cell >> sw.use_swept_grid >> sw.cell_prior >> sw.cell_prior_sweeps >> sw.p_unexplored;
				readSwept(in, m_sweptGrid);  // older streams: empty (internal_clear above)
			}
			m.sigma_corner = m.sigma_r;  // versions before 6: the paper's single sigma_r, no revisions
			insertionOptions.lasting.noisy_revisions = 0;
			if (version >= 6)
			{
				in >> m.sigma_corner >> insertionOptions.lasting.noisy_revisions;
				if (insertionOptions.lasting.noisy_revisions > 1000)
					THROW_EXCEPTION("CHierarchicalObjectMap: corrupt options (noisy_revisions above 1000)");
				m_lasting.setReviseSeq(in.ReadAs<uint64_t>());  // any value is valid (a round robin's start)
			}
			if (version >= 7) readMoveTypes(in, m_moveTypes);  // older streams: none (internal_clear above)
			m.size_moves = false;  // versions before 8: every table at its class's size
			if (version >= 8) readSizes(in, m, lasting);
			if (version >= 9)  // older streams: none stated (the pose spreads use the map's model)
			{
				in >> m_lastNoise.sigma_r >> m_lastNoise.sigma_phi >> m_lastNoise.sigma_tau;
				for (const double v : {m_lastNoise.sigma_r, m_lastNoise.sigma_phi, m_lastNoise.sigma_tau})
					if (!(v >= 0 && v <= 1e3))
						THROW_EXCEPTION("CHierarchicalObjectMap: corrupt sensor noise (not a number in [0, 1000])");
			}
			if (version >= 11) readLegSpreads(in, m);
			else  // older streams: every class's legs nominal
				for (auto& cl : m.classes) cl.leg_width_sigma = cl.texture_sigma = 0;
			insertionOptions.lasting.batch_sweeps = 1;  // versions before 12: every sweep annealed at once
			uint32_t pendingSweeps = 0;
			uint64_t pendingFrom = 0;
			if (version >= 12)
			{
				in >> insertionOptions.lasting.batch_sweeps >> pendingSweeps >> pendingFrom;
				if (insertionOptions.lasting.batch_sweeps < 1 || insertionOptions.lasting.batch_sweeps > 1000 ||
					pendingSweeps >= insertionOptions.lasting.batch_sweeps || pendingFrom > lasting.seq)
					THROW_EXCEPTION("CHierarchicalObjectMap: corrupt batch (batch_sweeps not in [1, 1000], or more "
									"sweeps pending than a batch, or pending contacts past the last)");
			}
			if (version >= 1)
			{
				m_lasting.state().restore(
					lasting.tables, lasting.existence, lasting.reported, lasting.legs, lasting.evidence, lasting.contacts,
					lasting.seq, m);
				m_lasting.state().restoreWalls(walls);
				m_lasting.setPending(pendingSweeps, pendingFrom);
				if (version >= 13) readChainSpreads(in, m_lasting.state());
			}
			m.manhattan_walls = false;  // versions before 14: walls at any yaw, as mapped in the likelihood
			likelihoodOptions.wall_extension = 0;
			if (version >= 14)
			{
				auto& lo = likelihoodOptions;
				in >> m.manhattan_walls >> m.wall_axis >> lo.wall_extension >> lo.wall_extension_min_length;
				if (!(std::abs(m.wall_axis) <= M_PI_2))
					THROW_EXCEPTION("CHierarchicalObjectMap: corrupt model (wall_axis not a number in [-pi/2, pi/2])");
				if (!(lo.wall_extension >= 0 && lo.wall_extension <= 100 && lo.wall_extension_min_length >= 0 &&
					  lo.wall_extension_min_length <= 100))
					THROW_EXCEPTION("CHierarchicalObjectMap: corrupt likelihood options (a wall extension not in [0, 100] m)");
			}
			insertionOptions.record_swept = true;  // versions before 15 recorded every sweep
			if (version >= 15) in >> insertionOptions.record_swept;
			insertionOptions.lasting.leg_merge_gap = 0;  // versions before 16 merged only overlapping legs
			if (version >= 16)
			{
				in >> insertionOptions.lasting.leg_merge_gap;
				if (!(insertionOptions.lasting.leg_merge_gap >= 0 && insertionOptions.lasting.leg_merge_gap <= 1))
					THROW_EXCEPTION("CHierarchicalObjectMap: corrupt options (leg_merge_gap not a number in [0, 1] m)");
			}
			likelihoodOptions.disjoint_tables = false;  // versions before 17: eq. 16 soft in the lasting map
			if (version >= 17) in >> likelihoodOptions.disjoint_tables;
			if (!(m.sigma_corner > 0) || !std::isfinite(m.sigma_corner))
				THROW_EXCEPTION("CHierarchicalObjectMap: corrupt model (sigma_corner not a positive number)");
			m_consolidator.setObjects(std::move(objs));
			m_consolidator.setOptions(c);
		}
		break;
		default:
			MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}
}  // namespace whiskermap::maps
