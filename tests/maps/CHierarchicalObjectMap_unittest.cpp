#include <gtest/gtest.h>
#include <numeric>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/model/ObjectCatalogue.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/World.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "StreamTail.h"

using namespace whiskermap;
using maps::CHierarchicalObjectMap;
using namespace maps::test;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
const std::string CONFIG = SRC + "/config/whisker-map.ini";

using TMode = CHierarchicalObjectMap::TInsertionOptions::TMode;

/** The shipped config's multimap after every sweep of a shipped dataset (built once). */
struct Mapped
{
	mrpt::maps::CMultiMetricMap multimap;
	obs::RawlogReader::Contents rawlog;
	CHierarchicalObjectMap::Ptr map;
	Mapped(const std::string& preset, TMode mode)
		: multimap(maps::MapConfig::load(CONFIG)),
		  rawlog(obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog")),
		  map(multimap.mapByClass<CHierarchicalObjectMap>())
	{
		map->insertionOptions.mode = mode;
		for (const auto& s : rawlog.sweeps) multimap.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
	}
};
const Mapped& defaultMapped()
{
	static const Mapped m("default", TMode::Lasting);
	return m;
}
const Mapped& perPoseMapped()
{
	static const Mapped m("default", TMode::PerPose);
	return m;
}

/** Everything the lasting state holds, as numbers: equal states give equal prints. */
std::string fingerprint(const CHierarchicalObjectMap& m)
{
	const auto& s = m.lastingMap().state();
	std::ostringstream o;
	o.precision(17);
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		if (s.hasTable(t)) o << "T" << s.table(t).x << "," << s.table(t).y << "," << s.table(t).theta << "," << s.existence(t) << "," << s.table(t).cls << ";";
	for (model::Id l = 0; l < s.legIdBound(); l++)
		if (s.hasLeg(l))
			o << "L" << s.leg(l).x << "," << s.leg(l).y << "," << s.leg(l).theta << "," << s.leg(l).parent << ","
			  << s.evidence(l).count() << "," << s.contactsOf(l).size() << ";";
	o << "C" << s.contactCount();
	return o.str();
}


/** The byte of a map stream that holds its version (after MRPT's class name). */
const size_t VERSION_BYTE = 1 + std::string("whiskermap::maps::CHierarchicalObjectMap").size();

/** `a` as the bytes of its stream. */
std::vector<uint8_t> bytesOf(const CHierarchicalObjectMap& a)
{
	mrpt::io::CMemoryStream buf;
	mrpt::serialization::archiveFrom(buf) << a;
	const auto* begin = static_cast<const uint8_t*>(buf.getRawBufferData());
	return {begin, begin + buf.getTotalBytesCount()};
}

/** A map read from stream bytes (null if they hold another object; throws if corrupt). */
std::shared_ptr<CHierarchicalObjectMap> fromBytes(std::vector<uint8_t> v)
{
	mrpt::io::CMemoryStream in;
	in.assignMemoryNotOwn(v.data(), v.size());
	return std::dynamic_pointer_cast<CHierarchicalObjectMap>(mrpt::serialization::archiveFrom(in).ReadObject());
}

/** `a` written to a stream and read back (null if it did not read back as a map). */
std::shared_ptr<CHierarchicalObjectMap> reloaded(const CHierarchicalObjectMap& a) { return fromBytes(bytesOf(a)); }

/** The lasting state as a sorted list of its tables and legs (a leg names its parent by the
 *  parent's position): independent of store ids, which a reload renumbers densely. */
std::vector<std::string> contentOf(const CHierarchicalObjectMap& m)
{
	const auto& s = m.lastingMap().state();
	std::vector<std::string> out;
	auto str = [](double v) { std::ostringstream o; o.precision(12); o << v; return o.str(); };
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		if (s.hasTable(t))
			out.push_back("T" + str(s.table(t).x) + "," + str(s.table(t).y) + "," + str(s.table(t).theta) + "," +
						  str(s.existence(t)) + "," + std::to_string(s.table(t).cls));
	for (model::Id l = 0; l < s.legIdBound(); l++)
		if (s.hasLeg(l))
		{
			const model::Leg& g = s.leg(l);
			const std::string parent = g.parent == model::NONE ? "-" : str(s.table(g.parent).x) + "," + str(s.table(g.parent).y);
			out.push_back("L" + str(g.x) + "," + str(g.y) + "," + str(g.wx) + "," + parent + "," + std::to_string(s.contactsExplained(l)));
		}
	std::sort(out.begin(), out.end());
	return out;
}

std::string configError(const std::string& text)
{
	const auto p = (std::filesystem::temp_directory_path() / "whiskermap_mapconfig.ini").string();
	std::ofstream(p) << text;
	try
	{
		maps::MapConfig::load(p);
	}
	catch (const core::Error& e)
	{
		return e.what();
	}
	return "loaded";
}
}  // namespace

TEST(CHierarchicalObjectMap, IsCreatedByNameFromTheShippedIni)
{
	mrpt::maps::CMultiMetricMap mm(maps::MapConfig::load(CONFIG));
	ASSERT_EQ(mm.maps.size(), 1u);
	auto map = mm.mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(map);
	EXPECT_TRUE(map->isEmpty());
	EXPECT_TRUE(map->lasting());
	EXPECT_EQ(map->insertionOptions.memory_size, 7u);
	EXPECT_DOUBLE_EQ(map->likelihoodOptions.min_existence, 0.5);
	EXPECT_EQ(map->likelihoodOptions.min_support, 3u);
	EXPECT_DOUBLE_EQ(map->modelParams.texture, 0.7);
}

TEST(CHierarchicalObjectMap, OfficeConfigNamesTheObjectCatalogue)
{
	// office-map.ini's `objects = objects.ini` is read relative to the config itself
	mrpt::maps::CMultiMetricMap mm(maps::MapConfig::load(SRC + "/config/office-map.ini"));
	auto map = mm.mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(map);
	EXPECT_EQ(map->modelParams.classes, model::ObjectCatalogue::load(SRC + "/config/objects.ini"));
	EXPECT_EQ(map->modelParams.classCount(), 4);
	mrpt::maps::CMultiMetricMap plain(maps::MapConfig::load(CONFIG));
	EXPECT_TRUE(plain.mapByClass<CHierarchicalObjectMap>()->modelParams.classes.empty());
	EXPECT_TRUE(map->modelParams.size_moves);  // office-map.ini infers sizes (eq. 24)
	EXPECT_TRUE(map->modelParams.free_space);  // and rules out walls across swept floor (eq. 25)
	EXPECT_FALSE(plain.mapByClass<CHierarchicalObjectMap>()->modelParams.size_moves);
	// size_moves (eq. 24) needs the catalogue: without one the config is refused by name.
	std::ifstream in(CONFIG);
	std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	const std::string model = "[MetricMap_hierarchicalObjectMap_00_model]\n";
	ASSERT_NE(text.find(model), std::string::npos);
	text.replace(text.find(model), model.size(), model + "size_moves = true\n");
	EXPECT_NE(configError(text).find("size_moves: needs an object catalogue"), std::string::npos) << configError(text);
}

TEST(CHierarchicalObjectMap, ConfigMistakesFailLoudly)
{
	const std::string ok = "[MetricMap]\nhierarchicalObjectMap_count=1\n";
	EXPECT_EQ(configError(ok), "loaded");
	EXPECT_NE(configError("[MetricMap]\nhierarchicalObjectMaps_count=1\n").find("unknown map type 'hierarchicalObjectMaps'"), std::string::npos);
	EXPECT_NE(configError("[MetricMap]\npointsMap_count=1\n").find("needs exactly one hierarchicalObjectMap, found 0"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_insertOpts]\nmemory_sise=7\n").find("memory_sise: unknown key"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_insertOpt]\nmemory_size=7\n").find("unknown section"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_likelihoodOpts]\np_miss=2\n").find("p_miss"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_model]\nsigma_r=0.01\n").find("missing required key"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_insertOpts]\nmode=lastin\n").find("'lastin' is not lasting or per_pose"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_likelihoodOpts]\nmin_existence=1.5\n").find("min_existence"), std::string::npos);
	EXPECT_NE(configError("[MetricMap]\n").find("needs exactly one"), std::string::npos);
	EXPECT_NE(configError(ok + "[MetricMap_hierarchicalObjectMap_00_insertOpts]\nlocal_temperatures=0\n").find("local_temperatures"), std::string::npos);
}

// The lasting map's own anneal schedule: the shipped configuration gives the built-in
// defaults, and each key reaches the map.
TEST(CHierarchicalObjectMap, LocalScheduleKeysReachTheMap)
{
	mrpt::maps::CMultiMetricMap shipped(maps::MapConfig::load(SRC + "/config/whisker-map.ini"));
	EXPECT_TRUE(shipped.mapByClass<CHierarchicalObjectMap>()->insertionOptions.lasting.schedule == maps::LastingMap::TOptions::TSchedule{});
	mrpt::config::CConfigFileMemory c(
		"[MetricMap]\nhierarchicalObjectMap_count=1\n[MetricMap_hierarchicalObjectMap_00_insertOpts]\n"
		"local_beta_start=0.5\nlocal_temperatures=3\nlocal_sweeps_per_temperature=2\nlocal_coldest_sweeps=5\nlocal_polish_sweeps=0\n");
	mrpt::maps::TSetOfMetricMapInitializers def;
	def.loadFromConfigFile(c, "MetricMap");
	mrpt::maps::CMultiMetricMap mm(def);
	const auto& s = mm.mapByClass<CHierarchicalObjectMap>()->insertionOptions.lasting.schedule;
	EXPECT_DOUBLE_EQ(s.beta_start, 0.5);
	EXPECT_EQ(s.temperatures, 3u);
	EXPECT_EQ(s.sweeps_per_temperature, 2u);
	EXPECT_EQ(s.coldest_sweeps, 5u);
	EXPECT_EQ(s.polish_sweeps, 0u);
}

// The lasting map of the default dataset: exactly the six tables, each within 3 mm and half
// a degree, certain, touched on at least two legs; no other table in the state.
TEST(CHierarchicalObjectMap, LastingMapHoldsEveryTableOfThePaperArena)
{
	const auto& m = defaultMapped();
	const auto truth = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	EXPECT_EQ(m.map->poseRecords().size(), 400u);
	const auto objects = m.map->mapObjects();
	ASSERT_EQ(objects.size(), truth.tables.size());
	EXPECT_TRUE(m.map->candidateObjects().empty());
	for (const auto& t : truth.tables)
	{
		bool found = false;
		for (const auto& o : objects)
			found = found || (std::hypot(o.table.x - t.x, o.table.y - t.y) < 0.003 &&
							  std::abs(core::angleDiff(o.table.yaw, t.yaw, M_PI)) < core::deg2rad(0.5) &&
							  o.existence > 0.99 && o.legs >= 2 && o.contacts >= 20);
		EXPECT_TRUE(found) << "table at " << t.x << ", " << t.y;
	}
	// Memory grows with objects: a leg keeps at most contacts_per_leg explicit contacts.
	const auto& s = m.map->lastingMap().state();
	for (model::Id l = 0; l < s.legIdBound(); l++)
		if (s.hasLeg(l))
		{
			EXPECT_LE(s.contactsOf(l).size(), m.map->insertionOptions.lasting.contacts_per_leg);
		}
}

// The paper's per-pose mode, as before: every table found at 3 or more poses.
TEST(CHierarchicalObjectMap, PerPoseModeFindsEveryTableOfThePaperArena)
{
	const auto& m = perPoseMapped();
	const auto truth = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	EXPECT_EQ(m.map->poseRecords().size(), 400u);
	for (const auto& t : truth.tables)
	{
		bool found = false;
		for (const auto& o : m.map->objects())
			found = found || (o.support >= 3 && std::hypot(o.table.x - t.x, o.table.y - t.y) < 0.1 &&
							  std::abs(core::angleDiff(o.table.yaw, t.yaw, M_PI)) < core::deg2rad(5));
		EXPECT_TRUE(found) << "table at " << t.x << ", " << t.y;
	}
	EXPECT_EQ(m.map->mapObjects().size() + m.map->candidateObjects().size(), m.map->objects().size());
}

TEST(CHierarchicalObjectMap, LikelihoodPeaksAtTheTruePoses)
{
	const auto& m = defaultMapped();
	// Sum over every sweep of the dataset, for the true poses shifted by a grid of offsets.
	auto total = [&](double dx, double dy, double dth) {
		double s = 0;
		for (const auto& sw : m.rawlog.sweeps)
			s += m.map->computeObservationLikelihood(
				*sw.obs, mrpt::poses::CPose3D(sw.robotPose + mrpt::poses::CPose2D(dx, dy, dth)));
		return s;
	};
	const double atTruth = total(0, 0, 0);
	for (double dx : {-0.1, -0.05, 0.0, 0.05, 0.1})
		for (double dy : {-0.1, -0.05, 0.0, 0.05, 0.1})
			for (double dth : {-0.1, 0.0, 0.1})
			{
				if (dx == 0 && dy == 0 && dth == 0) continue;
				EXPECT_LT(total(dx, dy, dth), atTruth) << dx << " " << dy << " " << dth;
			}
}

/** `map` written with MRPT's serialization and read back. */
static mrpt::maps::CMultiMetricMap roundTrip(const mrpt::maps::CMultiMetricMap& map)
{
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << map;
	buf.Seek(0);
	mrpt::maps::CMultiMetricMap back;
	arch >> back;
	return back;
}

TEST(CHierarchicalObjectMap, SerializationRoundTripThroughCMultiMetricMap)
{
	const auto& m = defaultMapped();
	const mrpt::maps::CMultiMetricMap back = roundTrip(m.multimap);
	auto b = back.mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(b);
	EXPECT_TRUE(b->lasting());
	EXPECT_EQ(fingerprint(*b), fingerprint(*m.map));
	EXPECT_GT(b->lastingMap().state().legCount(), 50u);
	ASSERT_EQ(b->poseRecords().size(), m.map->poseRecords().size());
	EXPECT_EQ(b->shapelets().size(), m.map->shapelets().size());
	ASSERT_FALSE(b->shapelets().empty());
	EXPECT_TRUE(m.map->shapelets().back().hasShaft());  // the shafts survive (version 2)
	EXPECT_EQ(b->shapelets().back().shaft_x, m.map->shapelets().back().shaft_x);
	EXPECT_EQ(b->shapelets().back().shaft_y, m.map->shapelets().back().shaft_y);
	EXPECT_EQ(b->modelParams, m.map->modelParams);
	EXPECT_EQ(b->proposed(), m.map->proposed());
	ASSERT_EQ(b->moveTypes().size(), m.map->moveTypes().size());  // version 7
	for (size_t k = 0; k < b->moveTypes().size(); k++)
	{
		EXPECT_EQ(b->moveTypes()[k].name, m.map->moveTypes()[k].name);
		EXPECT_EQ(b->moveTypes()[k].proposed, m.map->moveTypes()[k].proposed);
		EXPECT_EQ(b->moveTypes()[k].accepted, m.map->moveTypes()[k].accepted);
	}
	EXPECT_EQ(b->asString(), m.map->asString());
	// The reloaded map scores sweeps exactly as the original.
	const auto& s = m.rawlog.sweeps[200];
	EXPECT_EQ(b->computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(s.robotPose)),
			  m.map->computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(s.robotPose)));
}

// Version 2 stores the optional model keys (shaft noise, free space), not only their defaults;
// version 6 sigma_corner.
TEST(CHierarchicalObjectMap, SerializationKeepsTheOptionalModelKeys)
{
	CHierarchicalObjectMap a;
	a.modelParams.shaft_noise = a.modelParams.free_space = true;
	a.modelParams.sigma_across = 0.003;
	a.modelParams.free_space_p_miss = 0.2;
	a.modelParams.sigma_corner = 0.004;
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->modelParams, a.modelParams);
	EXPECT_FALSE(b->modelParams == model::ModelParams());
}

// The object catalogue and each lasting table's class survive the round trip (version 3), and
// the reloaded map continues exactly as the original (the office, where classes differ).
TEST(CHierarchicalObjectMap, SerializationKeepsTheObjectClasses)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/office/default.rawlog");
	CHierarchicalObjectMap a;
	a.modelParams.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
	const size_t half = rawlog.sweeps.size() / 2;
	for (size_t i = 0; i < half; i++) a.insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	std::set<std::string> classes;
	for (const auto& o : a.mapObjects()) classes.insert(o.table.object_class.str());
	EXPECT_GE(classes.size(), 2u);  // tables of more than one class to keep
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->modelParams, a.modelParams);
	EXPECT_TRUE(contentOf(*b) == contentOf(a));  // (not EXPECT_EQ: pages of output on failure)
	std::set<std::string> reloaded;
	for (const auto& o : b->mapObjects()) reloaded.insert(o.table.object_class.str());
	EXPECT_EQ(reloaded, classes);
	for (size_t i = half; i < half + 100 && i < rawlog.sweeps.size(); i++)
		for (auto* m : {&a, b.get()}) m->insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	EXPECT_TRUE(contentOf(*b) == contentOf(a));
}

// Version 11 stores each class's leg width and texture spreads (eq. 26); a version 10 stream
// (the same bytes without them) loads with spreads 0; a spread outside [0, 1] is refused.
TEST(CHierarchicalObjectMap, SerializationKeepsTheLegSpreads)
{
	CHierarchicalObjectMap a;
	a.modelParams.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
	for (auto& c : a.modelParams.classes) c.leg_width_sigma = 0.01, c.texture_sigma = 0.1;
	a.modelParams.classes[2].leg_width_sigma = 0.005;
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->modelParams, a.modelParams);
	const std::vector<uint8_t> bytes = bytesOf(a);
	ASSERT_EQ(bytes[VERSION_BYTE], STREAM_VERSION);
	// The tail before version 12's batch (16 bytes), version 13's chain spreads (none: no
	// table), the later versions' and MRPT's end flag: two doubles per class, class 2's leg
	// width spread first.
	const long tail = 16 * static_cast<long>(a.modelParams.classes.size()), batch = 16 + AFTER_CHAIN_SPREADS;
	std::vector<uint8_t> old = bytes;
	old[VERSION_BYTE] = 10;
	old.erase(old.end() - 1 - batch - tail, old.end() - 1);
	const auto c = fromBytes(old);
	ASSERT_TRUE(c);
	EXPECT_FALSE(c->modelParams.legsVary());
	EXPECT_EQ(c->modelParams.classes.size(), a.modelParams.classes.size());
	for (const double corrupt : {std::nan(""), -0.01, 2.0})
	{
		std::vector<uint8_t> bad = bytes;
		std::memcpy(bad.data() + bad.size() - 1 - batch - tail + 2 * 16, &corrupt, sizeof corrupt);
		EXPECT_ANY_THROW(fromBytes(bad)) << corrupt;
	}
}

// Version 12 stores the sweeps annealed together and those pending; a batch outside
// [1, 1000], more sweeps pending than a batch, or pending contacts past the last are refused.
TEST(CHierarchicalObjectMap, SerializationKeepsTheSweepsPending)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	CHierarchicalObjectMap a;
	a.insertionOptions.lasting.batch_sweeps = 4;
	for (size_t i = 0; a.lastingMap().pendingSweeps() < 2; i++)
		a.insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	EXPECT_EQ(a.lastingMap().state().legCount(), 0u);  // nothing annealed yet
	ASSERT_GT(a.lastingMap().state().contactCount(), 0u);
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->insertionOptions.lasting.batch_sweeps, 4u);
	EXPECT_EQ(b->lastingMap().pendingSweeps(), 2u);
	EXPECT_EQ(b->lastingMap().pendingFrom(), a.lastingMap().pendingFrom());
	const std::vector<uint8_t> bytes = bytesOf(a);
	ASSERT_TRUE(fromBytes(bytes));
	// Before the later versions' tails and MRPT's end flag (no table: no chain spreads):
	// batch_sweeps (uint32), sweeps pending (uint32), first pending seq (uint64).
	const size_t at = bytes.size() - 1 - AFTER_CHAIN_SPREADS - 16;
	const auto corrupt = [&](size_t offset, auto value) {
		std::vector<uint8_t> bad = bytes;
		std::memcpy(bad.data() + at + offset, &value, sizeof value);
		return bad;
	};
	EXPECT_ANY_THROW(fromBytes(corrupt(0, uint32_t{0})));
	EXPECT_ANY_THROW(fromBytes(corrupt(0, uint32_t{1001})));
	EXPECT_ANY_THROW(fromBytes(corrupt(4, uint32_t{4})));
	EXPECT_ANY_THROW(fromBytes(corrupt(8, uint64_t{1} << 40)));
	EXPECT_TRUE(fromBytes(corrupt(4, uint32_t{3})));
}

// Version 13 stores each lasting table's pose spread from the posterior chain (sampler key
// posterior_steps); a version 12 stream (the same bytes without them) loads with none, and a
// spread neither -1 (none) nor a number in [0, 1000] is refused.
TEST(CHierarchicalObjectMap, SerializationKeepsTheChainsPoseSpreads)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	CHierarchicalObjectMap a;
	a.samplerParams.posterior_steps = 1000;
	const auto& st = a.lastingMap().state();
	const auto known = [](const model::LastingState& s) {
		size_t n = 0;
		for (model::Id t = 0; t < s.tableIdBound(); t++) n += s.hasTable(t) && s.chainSpread(t).known();
		return n;
	};
	for (size_t i = 0; known(st) < 2; i++)
		a.insertObservation(*rawlog.sweeps.at(i).obs, mrpt::poses::CPose3D(rawlog.sweeps.at(i).robotPose));
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	const auto mine = a.mapObjects(true), theirs = b->mapObjects(true);
	ASSERT_EQ(mine.size(), theirs.size());
	for (size_t i = 0; i < mine.size(); i++)
	{
		EXPECT_EQ(theirs[i].sd_x, mine[i].sd_x);
		EXPECT_EQ(theirs[i].sd_y, mine[i].sd_y);
		EXPECT_EQ(theirs[i].sd_yaw, mine[i].sd_yaw);
	}
	EXPECT_EQ(known(b->lastingMap().state()), known(st));

	const std::vector<uint8_t> bytes = bytesOf(a);
	ASSERT_EQ(bytes[VERSION_BYTE], STREAM_VERSION);
	const long tail = 24 * static_cast<long>(st.tableCount());  // three doubles per table, before the later versions'
	std::vector<uint8_t> old = bytes;
	old[VERSION_BYTE] = 12;
	old.erase(old.end() - 1 - AFTER_CHAIN_SPREADS - tail, old.end() - 1);
	const auto c = fromBytes(old);
	ASSERT_TRUE(c);
	EXPECT_EQ(c->lastingMap().state().tableCount(), st.tableCount());
	EXPECT_EQ(known(c->lastingMap().state()), 0u);
	for (const double corrupt : {std::nan(""), -0.5, 2e3})
	{
		std::vector<uint8_t> bad = bytes;
		std::memcpy(bad.data() + bad.size() - 1 - AFTER_CHAIN_SPREADS - tail, &corrupt, sizeof corrupt);
		EXPECT_ANY_THROW(fromBytes(bad)) << corrupt;
	}
}

// Version 14 stores Manhattan walls (model keys manhattan_walls, wall_axis_deg) and the
// likelihood's wall extension; a version 13 stream (the same bytes without them) loads with
// walls at any yaw, as mapped in the likelihood, and an axis outside [-pi/2, pi/2] or an
// extension outside [0, 100] m is refused.
TEST(CHierarchicalObjectMap, SerializationKeepsManhattanWalls)
{
	CHierarchicalObjectMap a;
	a.modelParams.walls = a.modelParams.manhattan_walls = true;
	a.modelParams.wall_axis = 0.3;
	a.likelihoodOptions.wall_extension = 0.25;
	a.likelihoodOptions.wall_extension_min_length = 0.4;
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->modelParams, a.modelParams);
	EXPECT_EQ(b->likelihoodOptions.wall_extension, 0.25);
	EXPECT_EQ(b->likelihoodOptions.wall_extension_min_length, 0.4);
	const std::vector<uint8_t> bytes = bytesOf(a);
	ASSERT_EQ(bytes[VERSION_BYTE], STREAM_VERSION);
	std::vector<uint8_t> old = bytes;
	old[VERSION_BYTE] = 13;
	old.erase(old.end() - 1 - AFTER_CHAIN_SPREADS, old.end() - 1);
	const auto c = fromBytes(old);
	ASSERT_TRUE(c);
	EXPECT_FALSE(c->modelParams.manhattan_walls);
	EXPECT_FALSE(c->modelParams.wallAxis());
	EXPECT_EQ(c->likelihoodOptions.wall_extension, 0);
	for (const long at : {8 + 8 + 8, 8 + 8, 8})  // the axis, the extension, its minimum length
		for (const double corrupt : {std::nan(""), 2e3, -1.6})
		{
			std::vector<uint8_t> bad = bytes;
			std::memcpy(bad.data() + bad.size() - 1 - AFTER_MANHATTAN - at, &corrupt, sizeof corrupt);
			EXPECT_ANY_THROW(fromBytes(bad)) << corrupt << " at " << at;
		}
}

// Version 16 stores insertOpts leg_merge_gap; a version 15 stream (the same bytes without it)
// loads with 0 (only overlapping legs merged), and a gap outside [0, 1] m is refused.
TEST(CHierarchicalObjectMap, SerializationKeepsTheLegMergeGap)
{
	CHierarchicalObjectMap a;
	a.insertionOptions.lasting.leg_merge_gap = 0.02;
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->insertionOptions.lasting.leg_merge_gap, 0.02);
	const std::vector<uint8_t> bytes = bytesOf(a);
	ASSERT_EQ(bytes[VERSION_BYTE], STREAM_VERSION);
	std::vector<uint8_t> old = bytes;
	old[VERSION_BYTE] = 15;
	old.erase(old.end() - 1 - LEG_MERGE_GAP_BYTES - AFTER_LEG_MERGE_GAP, old.end() - 1);
	const auto c = fromBytes(old);
	ASSERT_TRUE(c);
	EXPECT_EQ(c->insertionOptions.lasting.leg_merge_gap, 0);
	for (const double corrupt : {std::nan(""), 2.0, -0.01})
	{
		std::vector<uint8_t> bad = bytes;
		std::memcpy(bad.data() + bad.size() - 1 - LEG_MERGE_GAP_BYTES - AFTER_LEG_MERGE_GAP, &corrupt, sizeof corrupt);
		EXPECT_ANY_THROW(fromBytes(bad)) << corrupt;
	}
}

// MRPT reads a field the stream's end cuts short without throwing: every cut of a map's stream
// is refused with an exception, never by running out of memory (a count read from a partial
// field can be huge).
// Version 17 stores likelihoodOpts disjoint_tables; a version 16 stream (the same bytes
// without it) loads with eq. 16 soft (false).
TEST(CHierarchicalObjectMap, SerializationKeepsDisjointTables)
{
	CHierarchicalObjectMap a;
	a.likelihoodOptions.disjoint_tables = true;
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_TRUE(b->likelihoodOptions.disjoint_tables);
	std::vector<uint8_t> old = bytesOf(a);
	ASSERT_EQ(old[VERSION_BYTE], STREAM_VERSION);
	old[VERSION_BYTE] = 16;
	old.erase(old.end() - 1 - DISJOINT_BYTES, old.end() - 1);
	const auto c = fromBytes(old);
	ASSERT_TRUE(c);
	EXPECT_FALSE(c->likelihoodOptions.disjoint_tables);
}

namespace
{
/** Pairs of the objects whose footprints meet. */
size_t overlappingPairs(const std::vector<maps::TMappedObject>& objects)
{
	size_t n = 0;
	for (size_t i = 0; i < objects.size(); i++)
		for (size_t j = i + 1; j < objects.size(); j++)
			n += objects[i].table.footprint().intersects(objects[j].table.footprint());
	return n;
}
}  // namespace

// likelihoodOpts disjoint_tables: eq. 16 made hard in the lasting map. Early in the paper
// arena, with min_existence 0, the map holds every hypothesis, and some overlap (a two-legged
// one beside a true table); with the rule, no two overlap, the one with the most contacts stays,
// every one left out overlaps one kept with at least as many contacts and is a candidate, and
// the likelihood's solids follow the option both ways.
TEST(CHierarchicalObjectMap, DisjointTablesKeepsTheBetterOfOverlappingTables)
{
	mrpt::maps::CMultiMetricMap multimap(maps::MapConfig::load(CONFIG));
	auto map = multimap.mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(map && map->lasting());
	map->likelihoodOptions.min_existence = 0;
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	size_t k = 0;
	for (; k < rawlog.sweeps.size() && overlappingPairs(map->mapObjects()) == 0; k++)
		multimap.insertObservation(*rawlog.sweeps[k].obs, mrpt::poses::CPose3D(rawlog.sweeps[k].robotPose));
	ASSERT_LT(k, rawlog.sweeps.size()) << "no two mapped tables overlapped after any sweep";
	const auto all = map->mapObjects();
	const size_t walls = map->mapWalls().size();
	EXPECT_EQ(map->mappedSolids().size(), 4 * all.size() + walls);

	map->likelihoodOptions.disjoint_tables = true;
	const auto kept = map->mapObjects(), left = map->candidateObjects();
	EXPECT_EQ(overlappingPairs(kept), 0u);
	EXPECT_EQ(kept.size() + left.size(), all.size());
	ASSERT_FALSE(left.empty());
	const auto contacts = [](const auto& a, const auto& b) { return a.contacts < b.contacts; };
	EXPECT_EQ(std::max_element(kept.begin(), kept.end(), contacts)->contacts,
			  std::max_element(all.begin(), all.end(), contacts)->contacts);
	for (const auto& l : left)
		EXPECT_TRUE(std::any_of(kept.begin(), kept.end(), [&](const auto& t) {
			return t.contacts >= l.contacts && t.table.footprint().intersects(l.table.footprint());
		})) << "a table left out overlaps none kept with as many contacts";
	EXPECT_EQ(map->mappedSolids().size(), 4 * kept.size() + walls);

	map->likelihoodOptions.disjoint_tables = false;
	EXPECT_EQ(map->mapObjects().size(), all.size());
	EXPECT_EQ(map->mappedSolids().size(), 4 * all.size() + walls);
}

TEST(CHierarchicalObjectMap, EveryTruncatedStreamIsRefused)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	CHierarchicalObjectMap a;
	for (size_t i = 0; a.lastingMap().state().tableCount() == 0; i++)  // a few legs, a table, contacts
		a.insertObservation(*rawlog.sweeps.at(i).obs, mrpt::poses::CPose3D(rawlog.sweeps.at(i).robotPose));
	const std::vector<uint8_t> bytes = bytesOf(a);
	for (size_t cut = 0; cut < bytes.size(); cut++)
	{
		bool refused = false;
		try
		{
			fromBytes({bytes.begin(), bytes.begin() + static_cast<long>(cut)});
		}
		catch (const std::bad_alloc&)
		{
			ADD_FAILURE() << "out of memory at a cut after " << cut << " of " << bytes.size() << " bytes";
			refused = true;
		}
		catch (const std::exception&)
		{
			refused = true;
		}
		EXPECT_TRUE(refused) << "a cut after " << cut << " of " << bytes.size() << " bytes read as a map";
	}
}

// The per-pose mode's consolidation survives the round trip too (objects and records).
TEST(CHierarchicalObjectMap, PerPoseSerializationRoundTrip)
{
	const auto& m = perPoseMapped();
	const mrpt::maps::CMultiMetricMap back = roundTrip(m.multimap);
	auto b = back.mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(b);
	EXPECT_FALSE(b->lasting());
	ASSERT_EQ(b->objects().size(), m.map->objects().size());
	for (size_t i = 0; i < b->objects().size(); i++)
	{
		EXPECT_EQ(b->objects()[i].table.x, m.map->objects()[i].table.x);
		EXPECT_EQ(b->objects()[i].support, m.map->objects()[i].support);
		EXPECT_EQ(b->objects()[i].evidence, m.map->objects()[i].evidence);
		EXPECT_EQ(b->objects()[i].contacts, m.map->objects()[i].contacts);
		EXPECT_EQ(b->objects()[i].legMask, m.map->objects()[i].legMask);
	}
	ASSERT_EQ(b->poseRecords().size(), m.map->poseRecords().size());
	EXPECT_EQ(b->poseRecords()[123].logPosterior, m.map->poseRecords()[123].logPosterior);
	EXPECT_EQ(b->asString(), m.map->asString());
}

// Lasting mode: a copy (as a particle filter makes) and a deserialized map continue exactly
// as the original; another seed gives another state. With shaft noise the contacts' shafts
// must survive too (a reload that lost them would score them isotropically). Very noisy
// sweeps run revisions (noisy_revisions), whose round robin must survive too. With sweeps
// annealed in batches (batch_sweeps) the copies are made with sweeps pending, which the
// copies must anneal as the original does.
static void expectLastingCopiesContinue(bool shaftNoise, const std::string& preset = "default", uint32_t batch = 1)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog");
	CHierarchicalObjectMap a, c;
	a.modelParams.shaft_noise = c.modelParams.shaft_noise = shaftNoise;
	a.insertionOptions.lasting.batch_sweeps = c.insertionOptions.lasting.batch_sweeps = batch;
	c.insertionOptions.seed = 99;
	size_t cut = 0;
	for (; cut < 120 || (batch > 1 && a.lastingMap().pendingSweeps() == 0); cut++)
	{
		const size_t i = cut;
		const mrpt::poses::CPose3D p(rawlog.sweeps[i].robotPose);
		a.insertObservation(*rawlog.sweeps[i].obs, p);
		c.insertObservation(*rawlog.sweeps[i].obs, p);
	}
	CHierarchicalObjectMap b = a;
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << a;
	buf.Seek(0);
	auto d = std::dynamic_pointer_cast<CHierarchicalObjectMap>(arch.ReadObject());
	ASSERT_TRUE(d);
	EXPECT_EQ(fingerprint(*d), fingerprint(a));
	for (const auto* m : {&b, d.get()})
	{
		EXPECT_EQ(m->lastingMap().pendingSweeps(), a.lastingMap().pendingSweeps());
		EXPECT_EQ(m->lastingMap().pendingFrom(), a.lastingMap().pendingFrom());
	}
	uint32_t revisions = 0;
	for (size_t i = cut; i < cut + 120; i++)
	{
		const mrpt::poses::CPose3D p(rawlog.sweeps[i].robotPose);
		for (auto* m : {&a, &b, d.get(), &c}) m->insertObservation(*rawlog.sweeps[i].obs, p);
		revisions += a.lastLastingStats().revisions;
	}
	for (auto* m : {&a, &b, d.get(), &c}) m->annealPending();
	EXPECT_EQ(revisions > 0, preset == "very-noisy");  // only sweeps noisier than sigma_corner
	EXPECT_EQ(fingerprint(b), fingerprint(a));
	EXPECT_EQ(fingerprint(*d), fingerprint(a));
	EXPECT_NE(fingerprint(c), fingerprint(a));
	a.clear();
	EXPECT_TRUE(a.isEmpty());
}

TEST(CHierarchicalObjectMap, LastingCopiesAndReloadsContinueIdentically) { expectLastingCopiesContinue(false); }
TEST(CHierarchicalObjectMap, LastingCopiesAndReloadsContinueIdenticallyWithShaftNoise)
{
	expectLastingCopiesContinue(true);
}
TEST(CHierarchicalObjectMap, LastingCopiesAndReloadsContinueIdenticallyWithRevisions)
{
	expectLastingCopiesContinue(false, "very-noisy");
}
TEST(CHierarchicalObjectMap, LastingCopiesAndReloadsContinueIdenticallyWithSweepsPending)
{
	expectLastingCopiesContinue(false, "default", 3);
}

TEST(CHierarchicalObjectMap, PerPoseSameSeedSameMapAndCopiesContinueIdentically)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	CHierarchicalObjectMap a, c;
	a.insertionOptions.mode = c.insertionOptions.mode = TMode::PerPose;
	c.insertionOptions.seed = 99;
	for (size_t i = 0; i < 100; i++)
	{
		const mrpt::poses::CPose3D p(rawlog.sweeps[i].robotPose);
		a.insertObservation(*rawlog.sweeps[i].obs, p);
		c.insertObservation(*rawlog.sweeps[i].obs, p);
	}
	CHierarchicalObjectMap b = a;  // a particle filter copies maps
	bool seedMatters = false;
	for (size_t i = 100; i < 200; i++)
	{
		const mrpt::poses::CPose3D p(rawlog.sweeps[i].robotPose);
		a.insertObservation(*rawlog.sweeps[i].obs, p);
		b.insertObservation(*rawlog.sweeps[i].obs, p);
		c.insertObservation(*rawlog.sweeps[i].obs, p);
	}
	ASSERT_EQ(a.poseRecords().size(), 200u);
	for (size_t i = 0; i < 200; i++)
	{
		EXPECT_EQ(a.poseRecords()[i].logPosterior, b.poseRecords()[i].logPosterior);
		seedMatters = seedMatters || a.poseRecords()[i].logPosterior != c.poseRecords()[i].logPosterior;
	}
	EXPECT_TRUE(seedMatters);
	a.clear();
	EXPECT_TRUE(a.isEmpty());
}

TEST(CHierarchicalObjectMap, IgnoresOtherObservations)
{
	CHierarchicalObjectMap m;
	mrpt::obs::CObservationOdometry odo;
	EXPECT_FALSE(m.insertObservation(odo));
	EXPECT_FALSE(m.canComputeObservationLikelihood(odo));
	EXPECT_TRUE(m.isEmpty());
}

TEST(CHierarchicalObjectMap, RevisionsMovesAreCountedWithTheInsertions)
{
	// Very noisy sweeps run revisions after the insertion (noisy_revisions); their moves count
	// in the insertion's tallies (summary.json's moves and move_types). Up to the first sweep
	// that runs one, a map without revisions holds the same state and anneals the insertion
	// the same way, so the difference is the revisions' own moves.
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/very-noisy.rawlog");
	CHierarchicalObjectMap with, without;
	without.insertionOptions.lasting.noisy_revisions = 0;
	const auto sum = [](const auto& counts) { return std::accumulate(counts.begin(), counts.end(), uint64_t{0}); };
	for (size_t i = 0; i < rawlog.sweeps.size(); i++)
	{
		const mrpt::poses::CPose3D p(rawlog.sweeps[i].robotPose);
		with.insertObservation(*rawlog.sweeps[i].obs, p);
		without.insertObservation(*rawlog.sweeps[i].obs, p);
		const auto &a = with.lastLastingStats(), &b = without.lastLastingStats();
		EXPECT_EQ(b.revisions, 0u);
		if (a.revisions == 0)
		{
			ASSERT_EQ(a.proposed, b.proposed) << i;
			continue;
		}
		EXPECT_GT(sum(a.proposed), sum(b.proposed));
		for (size_t m = 0; m < a.proposed.size(); m++)
		{
			EXPECT_GE(a.proposed[m], b.proposed[m]) << m;
			EXPECT_GE(a.accepted[m], b.accepted[m]) << m;
		}
		uint64_t byType = 0, acceptedByType = 0;
		for (const auto& t : a.moveTypes) byType += t.proposed, acceptedByType += t.accepted;
		EXPECT_EQ(byType, sum(a.proposed));
		EXPECT_EQ(acceptedByType, sum(a.accepted));
		return;
	}
	FAIL() << "no sweep ran a revision";
}
