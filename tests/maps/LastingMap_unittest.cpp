// The lasting map's promises (issue 7) on simulated sweeps: an earlier decision is revised
// when new evidence arrives (a mirror table found from two legs is replaced once a third leg
// is touched), and tables are found from contacts that no working-memory window holds
// together (the sparse evaluation paths, config/worlds/eval/sparse).
#include <gtest/gtest.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/TouchAudit.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <array>
#include <set>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

using namespace whiskermap;
using maps::CHierarchicalObjectMap;
using mrpt::poses::CPose2D;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
using TMode = CHierarchicalObjectMap::TInsertionOptions::TMode;

const world::Robot& scratchbot()
{
	static const world::Robot r = world::Robot::load(SRC + "/config/robots/scratchbot.ini");
	return r;
}

/** The shipped whisker-map configuration's map, in the given mode. */
struct Map
{
	mrpt::maps::CMultiMetricMap multimap;
	CHierarchicalObjectMap::Ptr map;
	explicit Map(TMode mode)
		: multimap(maps::MapConfig::load(SRC + "/config/whisker-map.ini")), map(multimap.mapByClass<CHierarchicalObjectMap>())
	{
		map->insertionOptions.mode = mode;
	}
	void insert(world::WhiskerSimulator& sim, const CPose2D& pose)
	{
		const auto sweep = sim.sense(pose, mrpt::Clock::fromDouble(0));
		multimap.insertObservation(*sweep, mrpt::poses::CPose3D(pose));
	}
};

/** Centre within `dist` metres and yaw (mod 180 degrees) within `deg` degrees. */
bool near(const world::Table& a, const world::Table& b, double dist, double deg)
{
	return std::hypot(a.x - b.x, a.y - b.y) <= dist && std::abs(core::angleDiff(a.yaw, b.yaw, M_PI)) <= core::deg2rad(deg);
}

/** Map objects near table `t`. */
size_t countNear(const std::vector<maps::TMappedObject>& objects, const world::Table& t, double dist, double deg)
{
	size_t n = 0;
	for (const auto& o : objects) n += near(o.table, t, dist, deg);
	return n;
}

/** One table of the paper's size, yaw 0, in a 6 x 6 m arena (walls out of whisker reach). */
world::World oneTable(double x, double y)
{
	world::World w;
	w.x_min = w.y_min = -3;
	w.x_max = w.y_max = 3;
	w.tables.push_back(world::Table{x, y, 0, 1.0, 0.6, 0.05, 0.7});
	return w;
}

/** The leg of table 0 of `w` centred at `c`. */
int legAt(const world::World& w, const Eigen::Vector2d& c)
{
	for (int k = 0; k < 4; k++)
		if ((w.tables[0].legCentre(k) - c).norm() < 1e-9) return k;
	return -1;
}

/** Poses that touch the leg centred at `c` (two contacts or more) and nothing else, in
 *  every world of `worlds` (noiseless truth): the robot 15-45 cm from the leg, every 15
 *  degrees around it, every 30 degrees of heading; at most `n` of them, spread over the scan. */
std::vector<CPose2D> posesTouchingOnly(const std::vector<world::World>& worlds, const Eigen::Vector2d& c, size_t n)
{
	std::vector<CPose2D> found;
	std::vector<world::WhiskerSimulator::Truth> truth;
	for (int ring = 0; ring < 4; ring++)
		for (int around = 0; around < 24; around++)
			for (int heading = 0; heading < 12; heading++)
			{
				const double r = 0.15 + 0.1 * ring, a = core::deg2rad(15 * around);
				const CPose2D pose(c.x() + r * std::cos(a), c.y() + r * std::sin(a), core::deg2rad(30 * heading));
				bool only = true;
				for (const auto& w : worlds)
				{
					const int leg = legAt(w, c);
					world::WhiskerSimulator sim(w, scratchbot(), {}, 1);
					if (!sim.poseIsFree(pose))
					{
						only = false;
						break;
					}
					const auto sweep = sim.sense(pose, mrpt::Clock::fromDouble(0), &truth);
					size_t onLeg = 0;
					for (size_t i = 0; i < sweep->whiskers.size(); i++)
					{
						if (!sweep->whiskers[i].touched) continue;
						only = only && truth[i].table == 0 && truth[i].leg == leg;
						onLeg++;
					}
					only = only && onLeg >= 2;
				}
				if (only) found.push_back(pose);
			}
	// Spread the choice over the scan: different sides and distances.
	std::vector<CPose2D> out;
	for (size_t i = 0; i < n && !found.empty(); i++) out.push_back(found[i * found.size() / n]);
	return out;
}
}  // namespace

// Two legs on a long side of a table are explained equally well by the table and by its
// mirror image across them. The same first sweeps are inserted in two worlds, one holding the
// table and the other its mirror image, so in at least one of them the map first holds the
// wrong table; a sweep on a third leg (which differs between the worlds) must then replace it
// by the true table, and no mirror may remain in the map.
TEST(LastingMap, MirrorTableIsCorrectedWhenAThirdLegIsTouched)
{
	// Legs 0 (+x+y) and 1 (-x+y) of the table at (0, 0) are legs 3 (+x-y) and 2 (-x-y) of its
	// mirror image at (0, 0.6). The third leg: 3 (+x-y) of the first, 0 (+x+y) of the second.
	const world::World worlds[2] = {oneTable(0, 0), oneTable(0, 0.6)};
	const Eigen::Vector2d thirdLeg[2] = {{0.5, -0.3}, {0.5, 0.9}};
	const std::vector<world::World> both(std::begin(worlds), std::end(worlds));
	const auto legA = posesTouchingOnly(both, {0.5, 0.3}, 2), legB = posesTouchingOnly(both, {-0.5, 0.3}, 2);
	ASSERT_EQ(legA.size(), 2u);
	ASSERT_EQ(legB.size(), 2u);
	const auto noise = world::NoisePreset::load(SRC + "/config/noise/default.ini");

	int mirrorsFirst = 0;
	std::vector<obs::Shapelet> first[2];  // the contacts of the first sweeps, per world
	for (int k = 0; k < 2; k++)
	{
		SCOPED_TRACE("world with the table at y = " + std::to_string(worlds[k].tables[0].y));
		const world::Table& truth = worlds[k].tables[0];
		const world::Table& mirror = worlds[1 - k].tables[0];
		Map m(TMode::Lasting);
		world::WhiskerSimulator sim(worlds[k], scratchbot(), noise, 7);
		for (size_t i = 0; i < 2; i++) m.insert(sim, legA[i]), m.insert(sim, legB[i]);
		first[k] = m.map->shapelets();

		// Two legs: the state holds one table through them, the true one or its mirror.
		std::vector<maps::TMappedObject> all = m.map->mapObjects(), candidates = m.map->candidateObjects();
		all.insert(all.end(), candidates.begin(), candidates.end());
		ASSERT_EQ(all.size(), 1u);
		const bool wasMirror = near(all[0].table, mirror, 0.02, 2);
		EXPECT_TRUE(wasMirror || near(all[0].table, truth, 0.02, 2)) << all[0].table.x << ", " << all[0].table.y;
		EXPECT_EQ(all[0].legs, 2u);
		EXPECT_GT(all[0].existence, 0.2);  // about one half: the mirror is as likely
		EXPECT_LT(all[0].existence, 0.8);
		mirrorsFirst += wasMirror;

		// A third leg: the true table, certain, and nothing else in the map.
		for (const auto& pose : posesTouchingOnly({worlds[k]}, thirdLeg[k], 2)) m.insert(sim, pose);
		const auto objects = m.map->mapObjects();
		ASSERT_EQ(objects.size(), 1u);
		EXPECT_TRUE(near(objects[0].table, truth, 0.004, 1))
			<< "found " << objects[0].table.x << ", " << objects[0].table.y << ", "
			<< core::rad2deg(objects[0].table.yaw) << " deg";
		EXPECT_GT(objects[0].existence, 0.99);
		EXPECT_EQ(objects[0].legs, 3u);
		EXPECT_EQ(countNear(objects, mirror, 0.1, 5), 0u);
		EXPECT_EQ(countNear(m.map->candidateObjects(), mirror, 0.1, 5), 0u);
	}
	// The first sweeps were the same in both worlds, so one of them began with the mirror.
	ASSERT_EQ(first[0].size(), first[1].size());
	for (size_t i = 0; i < first[0].size(); i++)
	{
		EXPECT_EQ(first[0][i].x, first[1][i].x);
		EXPECT_EQ(first[0][i].y, first[1][i].y);
		EXPECT_EQ(first[0][i].normal, first[1][i].normal);
	}
	EXPECT_EQ(mirrorsFirst, 1);
}

// The same two legs with the posterior chain (sampler key posterior_steps, doc/sampler.md "A
// posterior from a chain"): the table's existence is the fraction of the chain's samples
// holding it. With its mirror image as likely, that is about one half; once the third leg is
// touched the table is certain.
TEST(LastingMap, PosteriorChainGivesAMirrorPairHalfItsExistence)
{
	const world::World w = oneTable(0, 0), mirror = oneTable(0, 0.6);
	const auto legA = posesTouchingOnly({w, mirror}, {0.5, 0.3}, 2), legB = posesTouchingOnly({w, mirror}, {-0.5, 0.3}, 2);
	ASSERT_EQ(legA.size(), 2u);
	ASSERT_EQ(legB.size(), 2u);
	Map m(TMode::Lasting);
	m.map->samplerParams.posterior_steps = 20000;
	world::WhiskerSimulator sim(w, scratchbot(), world::NoisePreset::load(SRC + "/config/noise/default.ini"), 7);
	for (size_t i = 0; i < 2; i++) m.insert(sim, legA[i]), m.insert(sim, legB[i]);
	std::vector<maps::TMappedObject> all = m.map->mapObjects(), candidates = m.map->candidateObjects();
	all.insert(all.end(), candidates.begin(), candidates.end());
	ASSERT_EQ(all.size(), 1u);
	std::printf("two legs: existence %.3f\n", all[0].existence);
	EXPECT_GT(all[0].existence, 0.35);
	EXPECT_LT(all[0].existence, 0.65);
	for (const auto& pose : posesTouchingOnly({w}, {0.5, -0.3}, 2)) m.insert(sim, pose);
	const auto objects = m.map->mapObjects();
	ASSERT_EQ(objects.size(), 1u);
	std::printf("three legs: existence %.3f\n", objects[0].existence);
	EXPECT_TRUE(near(objects[0].table, w.tables[0], 0.004, 1));
	EXPECT_GT(objects[0].existence, 0.95);

	// map_tables.csv's spread is the chain's: the spread of the table's pose over its samples,
	// of the order of sigma_corner / sqrt(contacts), not RigidPoseSpread's (another chain).
	const auto& st = m.map->lastingMap().state();
	model::Id t = 0;
	while (!st.hasTable(t)) t++;
	const auto chain = st.chainSpread(t);
	const auto reported = m.map->mapObjects(true);
	ASSERT_TRUE(chain.known());
	std::printf("chain spread: %.2f mm, %.2f mm, %.3f deg\n", 1e3 * chain.sd_x, 1e3 * chain.sd_y, core::rad2deg(chain.sd_yaw));
	EXPECT_EQ(reported[0].sd_x, chain.sd_x);
	EXPECT_EQ(reported[0].sd_y, chain.sd_y);
	EXPECT_EQ(reported[0].sd_yaw, chain.sd_yaw);
	for (const double sd : {chain.sd_x, chain.sd_y}) EXPECT_TRUE(sd > 2e-4 && sd < 0.01) << sd;
	EXPECT_TRUE(chain.sd_yaw > core::deg2rad(0.02) && chain.sd_yaw < core::deg2rad(2)) << chain.sd_yaw;
	m.map->samplerParams.posterior_steps = 0;  // a table scored without the chain reports none
	for (const auto& pose : posesTouchingOnly({w}, {-0.5, -0.3}, 1)) m.insert(sim, pose);
	const auto plain = m.map->mapObjects(true);
	ASSERT_EQ(plain.size(), 1u);
	EXPECT_NE(plain[0].sd_x, chain.sd_x);
	t = 0;
	while (!st.hasTable(t)) t++;
	EXPECT_FALSE(st.chainSpread(t).known());
}

// A shipped sparse evaluation path (doc/eval-worlds.md): no 7 consecutive contacts hold two
// legs of one table, yet every table is touched on three legs over the run. The lasting map
// finds all six tables from contacts far apart in time; the paper's per-pose mode, which
// sees 7 contacts at a time, finds none.
TEST(LastingMap, FindsTablesOnlyAcrossWindowsOnASparsePath)
{
	const std::string base = SRC + "/config/worlds/eval/sparse/seed1";
	const auto world = world::World::load(base + ".ini");
	const auto path = world::Trajectory::readPathFile(base + ".path");
	const auto noise = world::NoisePreset::load(SRC + "/config/noise/default.ini");
	const uint64_t seed = 1;  // whisker-sim --seed, as the path was checked with

	// The path's promise, on the contacts the maps receive (simulator truth).
	const auto audit = world::TouchAudit::run(world, scratchbot(), noise, seed, path);
	ASSERT_GE(audit.closestCrossLegSpacing(), 7u);
	ASSERT_EQ(audit.identifiable(), world.tables.size());

	Map lasting(TMode::Lasting), perPose(TMode::PerPose);
	for (Map* m : {&lasting, &perPose})
	{
		world::WhiskerSimulator sim(world, scratchbot(), noise, seed);
		for (const auto& pose : path)
			if (sim.poseIsFree(pose)) m->insert(sim, pose);
	}
	ASSERT_EQ(lasting.map->steps(), path.size() - audit.blockedPoses);

	const auto found = lasting.map->mapObjects(), perPoseFound = perPose.map->mapObjects();
	EXPECT_EQ(found.size(), world.tables.size());
	for (const auto& t : world.tables)
	{
		EXPECT_EQ(countNear(found, t, 0.01, 1), 1u) << "lasting map: table at " << t.x << ", " << t.y;
		// whisker-eval's gates (25 cm, 20 degrees): the per-pose map has nothing near it.
		EXPECT_EQ(countNear(perPoseFound, t, 0.25, 20), 0u) << "per-pose map: table at " << t.x << ", " << t.y;
	}
}

// The reported pose (insertOpts rigid_pose, doc/map-plugin.md): each table refitted with its
// legs rigid at its corners to every contact they explain, each contact uncertain along its
// shaft. On the sparse path (about six contacts per leg) it is closer to the truth than the
// model's own table pose, whose legs are loose at its corners (eq. 6); the model's state,
// existence and data association are the same either way.
TEST(LastingMap, RigidPoseIsCloserToTheTruthOnASparsePath)
{
	const std::string base = SRC + "/config/worlds/eval/sparse/seed1";
	const auto world = world::World::load(base + ".ini");
	const auto path = world::Trajectory::readPathFile(base + ".path");
	const auto noise = world::NoisePreset::load(SRC + "/config/noise/default.ini");
	double sum2[2] = {0, 0};
	for (const bool rigid : {false, true})
	{
		Map m(TMode::Lasting);
		m.map->insertionOptions.lasting.rigid_pose = rigid;
		world::WhiskerSimulator sim(world, scratchbot(), noise, 1);
		for (const auto& pose : path)
			if (sim.poseIsFree(pose)) m.insert(sim, pose);
		const auto found = m.map->mapObjects();
		ASSERT_EQ(found.size(), world.tables.size());
		for (const auto& t : world.tables)
		{
			double best = 1e9;
			for (const auto& o : found) best = std::min(best, std::hypot(o.table.x - t.x, o.table.y - t.y));
			sum2[rigid] += best * best;
		}
		const auto& s = m.map->lastingMap().state();
		for (model::Id t = 0; t < s.tableIdBound(); t++)
		{
			if (!s.hasTable(t) || rigid) continue;
			EXPECT_EQ(s.reported(t).x, s.table(t).x);  // off: the model's pose as it is
		}
	}
	const double n = static_cast<double>(world.tables.size());
	const double loose = std::sqrt(sum2[0] / n), rigid = std::sqrt(sum2[1] / n);
	EXPECT_LT(rigid, 0.7 * loose) << "rigid " << rigid << " m, loose " << loose << " m";
	EXPECT_LT(rigid, 0.0025);  // whisker-eval on the same run: 1.7 mm (the model's pose: 3.4 mm)
}

/** The sparse evaluation path of world seed1 at default noise, into a lasting map that anneals
 *  its sweeps in batches of 3. */
struct SparseInBatches
{
	const std::string base = SRC + "/config/worlds/eval/sparse/seed1";
	world::World world = world::World::load(base + ".ini");
	std::vector<CPose2D> path = world::Trajectory::readPathFile(base + ".path");
	world::WhiskerSimulator sim{world, scratchbot(), world::NoisePreset::load(SRC + "/config/noise/default.ini"), 1};
	Map m{TMode::Lasting};
	SparseInBatches() { m.map->insertionOptions.lasting.batch_sweeps = 3; }
};

// Sweeps annealed together (insertOpts batch_sweeps): a sweep's contacts join the map at once,
// unexplained, and are annealed with those of the next sweeps when the batch is full, or at
// annealPending(). Batches of 3 on the sparse path find every table as single sweeps do.
TEST(LastingMap, SweepsAnnealedInBatchesFindTheTablesOnASparsePath)
{
	SparseInBatches b;
	const auto& world = b.world;
	auto& sim = b.sim;
	Map& m = b.m;
	const auto& lasting = m.map->lastingMap();
	bool sawPending = false, sawAnnealed = false;
	for (const auto& pose : b.path)
	{
		if (!sim.poseIsFree(pose)) continue;
		const uint32_t before = lasting.pendingSweeps();
		const size_t contacts = lasting.state().contactCount();
		m.insert(sim, pose);
		if (lasting.state().contactCount() == contacts) continue;  // touched nothing: not a batch's sweep
		if (before < 2)
		{
			// Pending: this sweep's contacts are held, none explained yet.
			EXPECT_EQ(lasting.pendingSweeps(), before + 1);
			for (model::Id c = 0; c < lasting.state().contactIdBound(); c++)
				if (lasting.state().hasContact(c) && lasting.state().contact(c).seq >= lasting.pendingFrom())
				{
					EXPECT_EQ(lasting.state().contact(c).leg, model::NONE);
				}
			sawPending = true;
		}
		else
		{
			EXPECT_EQ(lasting.pendingSweeps(), 0u);
			EXPECT_TRUE(m.map->lastLastingStats().changed);
			sawAnnealed = true;
		}
	}
	EXPECT_TRUE(sawPending && sawAnnealed);
	m.map->annealPending();
	EXPECT_EQ(lasting.pendingSweeps(), 0u);
	const auto found = m.map->mapObjects();
	EXPECT_EQ(found.size(), world.tables.size());
	for (const auto& t : world.tables) EXPECT_EQ(countNear(found, t, 0.01, 1), 1u) << "table at " << t.x << ", " << t.y;
}

// Stock tools (rbpf-slam) save the map with saveMetricMapRepresentationToFile and never call
// annealPending(): the files hold the map with its pending sweeps annealed (on a copy), and
// the map keeps them pending. Checked where the pending contacts change the map's tables, so
// saving the unannealed map would write another map_tables.csv.
TEST(LastingMap, SavedRepresentationAnnealsThePendingSweepsOnACopy)
{
	SparseInBatches b;
	auto& sim = b.sim;
	Map& m = b.m;
	const auto& lasting = m.map->lastingMap();
	const std::string dir = ::testing::TempDir();
	const auto read = [](const std::string& path) {
		std::ifstream in(path);
		return std::string(std::istreambuf_iterator<char>(in), {});
	};
	bool checked = false;
	for (const auto& pose : b.path)
	{
		if (!sim.poseIsFree(pose)) continue;
		m.insert(sim, pose);
		if (lasting.pendingSweeps() == 0) continue;
		CHierarchicalObjectMap copy(*m.map);
		copy.annealPending();
		if (copy.mapObjects(true).size() == m.map->mapObjects(true).size()) continue;
		const uint32_t pending = lasting.pendingSweeps();
		m.map->saveMetricMapRepresentationToFile(dir + "saved");
		copy.saveMetricMapRepresentationToFile(dir + "annealed");
		EXPECT_EQ(lasting.pendingSweeps(), pending);
		EXPECT_FALSE(read(dir + "saved_map_tables.csv").empty());
		EXPECT_EQ(read(dir + "saved_map_tables.csv"), read(dir + "annealed_map_tables.csv"));
		EXPECT_EQ(read(dir + "saved_map_candidates.csv"), read(dir + "annealed_map_candidates.csv"));
		checked = true;
		break;
	}
	EXPECT_TRUE(checked);
}

// The working memory of an insertion (samplers, local problem, scratch) is the thread's
// (LastingWorkspace), shared by every lasting map on it: maps inserting in turn, one of them
// with other sampler settings (so that the workspace is rebuilt at every turn), end exactly
// where each ends alone.
TEST(LastingMap, MapsInsertingInTurnEndAsEachAlone)
{
	const std::string base = SRC + "/config/worlds/eval/sparse/seed1";
	const auto world = world::World::load(base + ".ini");
	world::WhiskerSimulator sim(world, scratchbot(), world::NoisePreset::load(SRC + "/config/noise/default.ini"), 1);
	std::vector<std::pair<CPose2D, mrpt::obs::CObservation::Ptr>> sweeps;
	for (const auto& pose : world::Trajectory::readPathFile(base + ".path"))
		if (sim.poseIsFree(pose)) sweeps.emplace_back(pose, sim.sense(pose, mrpt::Clock::fromDouble(0)));
	const auto make = [](bool other) {
		auto m = std::make_unique<Map>(TMode::Lasting);
		if (other) m->map->samplerParams.r1 = 0.05;  // fewer deaths proposed
		return m;
	};
	const auto tables = [](const Map& m) {  // and the moves proposed over the run, which the settings change
		std::vector<std::array<double, 3>> out;
		for (const auto& o : m.map->mapObjects()) out.push_back({o.table.x, o.table.y, o.table.yaw});
		for (const uint64_t n : m.map->proposed()) out.push_back({double(n), 0, 0});
		return out;
	};
	std::vector<std::array<double, 3>> alone[2];
	for (const bool other : {false, true})
	{
		auto m = make(other);
		for (const auto& [pose, obs] : sweeps) m->multimap.insertObservation(*obs, mrpt::poses::CPose3D(pose));
		alone[other] = tables(*m);
	}
	auto a = make(false), b = make(true);
	for (const auto& [pose, obs] : sweeps)
		for (Map* m : {a.get(), b.get()}) m->multimap.insertObservation(*obs, mrpt::poses::CPose3D(pose));
	EXPECT_EQ(tables(*a), alone[0]);
	EXPECT_EQ(tables(*b), alone[1]);
	EXPECT_NE(alone[0], alone[1]);  // the other settings do change the run
}

// A copy of a lasting map (as a particle filter's resampling makes) shares the legs' folded
// evidence and the contacts' readings with its original; a sweep inserted into the copy gives
// it its own evidence where it folds and its own readings for the new contacts, shares the
// rest still, and leaves the original as it was.
TEST(LastingMap, CopiesShareEvidenceAndReadingsUntilTheyChange)
{
	const world::World w = oneTable(0, 0);
	world::WhiskerSimulator sim(w, scratchbot(), world::NoisePreset::load(SRC + "/config/noise/default.ini"), 1);
	const auto touching = [&](int leg) { return posesTouchingOnly({w}, w.tables[0].legCentre(leg), 8); };
	Map a(TMode::Lasting);
	for (const int leg : {0, 1})
		for (const auto& pose : touching(leg)) a.insert(sim, pose);
	const model::LastingState& sa = a.map->lastingMap().state();
	// What a copy may share: the original's evidence objects and readings, and their values.
	std::set<const void*> shared;
	std::vector<std::array<double, model::LegEvidence::STATS>> evidenceBefore;
	for (model::Id l = 0; l < sa.legIdBound(); l++)
		if (sa.hasLeg(l) && !sa.evidence(l).empty())
			shared.insert(&sa.evidence(l)), evidenceBefore.push_back(sa.evidence(l).stats());
	const size_t folded = shared.size();
	for (model::Id c = 0; c < sa.contactIdBound(); c++)
		if (sa.hasContact(c)) shared.insert(&sa.shapelet(c));
	ASSERT_GT(folded, 0u);
	ASSERT_GT(shared.size(), folded);

	CHierarchicalObjectMap copy(*a.map);
	const model::LastingState& sb = copy.lastingMap().state();
	// The copy's evidence objects (legs) or readings (contacts), shared with the original or its own.
	const auto count = [&](bool legs, bool inShared) {
		size_t n = 0;
		for (model::Id l = 0; legs && l < sb.legIdBound(); l++)
			if (sb.hasLeg(l) && !sb.evidence(l).empty()) n += shared.count(&sb.evidence(l)) == inShared;
		for (model::Id c = 0; !legs && c < sb.contactIdBound(); c++)
			if (sb.hasContact(c)) n += shared.count(&sb.shapelet(c)) == inShared;
		return n;
	};
	EXPECT_EQ(count(true, true) + count(false, true), shared.size());  // a fresh copy shares everything
	EXPECT_EQ(count(true, false) + count(false, false), 0u);

	for (const auto& pose : touching(2))  // the table's far leg
		copy.insertObservation(*sim.sense(pose, mrpt::Clock::fromDouble(0)), mrpt::poses::CPose3D(pose));
	// Legs 0 and 1 are on the board of leg 2's insertions (a table diagonal away) and come
	// back from it unchanged: their evidence is still the original's.
	EXPECT_EQ(count(true, true), folded);
	EXPECT_GT(count(false, true), 0u);  // so are their explicit contacts' readings
	EXPECT_GT(count(false, false), 0u);  // the copy's own: leg 2's readings
	std::vector<std::array<double, model::LegEvidence::STATS>> evidenceAfter;
	for (model::Id l = 0; l < sa.legIdBound(); l++)
		if (sa.hasLeg(l) && !sa.evidence(l).empty()) evidenceAfter.push_back(sa.evidence(l).stats());
	EXPECT_EQ(evidenceAfter, evidenceBefore);  // the original is as it was
}
