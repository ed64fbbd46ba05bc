// Walls in the lasting map (doc/map-plugin.md, "Walls"): a line of contacts along a wall
// becomes one wall and no object; the walls survive serialization and a reloaded map continues
// as the original.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/inference/SamplerParams.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/LastingMap.h>
#include <whiskermap/maps/SweepLikelihood.h>
#include <whiskermap/model/ObjectCatalogue.h>
#include <whiskermap/model/SweptGrid.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "StreamTail.h"

using namespace whiskermap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

/** Inserts sweeps of 2-3 contacts on face +1 of the wall y in [-0.1, 0] from x = 0 to 3 m
 *  (normals +90 deg, 3 mm and 3 deg of noise, wall texture), as a robot whisking along it. */
maps::LastingMap wallRun(bool walls, uint64_t seed)
{
	model::ModelParams p;
	p.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
	p.walls = walls;
	const inference::SamplerParams s;
	maps::LastingMap m;
	std::mt19937_64 rng(seed);
	std::normal_distribution<double> n(0, 1);
	for (int k = 0; k < 40; k++)
	{
		std::vector<obs::Shapelet> sweep;
		const double x = 0.07 * k;
		for (int i = 0; i < 2 + k % 2; i++)
		{
			obs::Shapelet c;
			c.x = x + 0.12 * i + 0.003 * n(rng), c.y = 0.003 * n(rng);
			c.normal = M_PI_2 + 0.05 * n(rng), c.texture = 0.3 + 0.02 * n(rng);
			sweep.push_back(c);
		}
		m.insert(sweep, p, s, seed * 1000 + static_cast<uint64_t>(k));
	}
	return m;
}

size_t tablesAbove(const model::LastingState& s, double existence)
{
	size_t n = 0;
	for (model::Id t = 0; t < s.tableIdBound(); t++) n += s.hasTable(t) && s.existence(t) >= existence;
	return n;
}

std::shared_ptr<maps::CHierarchicalObjectMap> reloaded(const maps::CHierarchicalObjectMap& a)
{
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << a;
	buf.Seek(0);
	return std::dynamic_pointer_cast<maps::CHierarchicalObjectMap>(arch.ReadObject());
}
}  // namespace

TEST(WallMap, ALineOfContactsBecomesAWallAndNoChair)
{
	for (uint64_t seed = 1; seed <= 3; seed++)
	{
		const maps::LastingMap m = wallRun(true, seed);
		const model::LastingState& s = m.state();
		EXPECT_EQ(tablesAbove(s, 0.5), 0u) << seed;
		size_t strong = 0;
		double length = 0;
		for (const auto& w : s.walls())
			if (w.existence >= 0.5) strong++, length += w.wall.length();
		EXPECT_GE(strong, 1u) << seed;
		EXPECT_GT(length, 2.0) << seed;  // contacts span 0 .. 2.97 m; the first few stay on legs
		for (const auto& w : s.walls())  // along the line y = -0.05 (the face at y = 0)
		{
			EXPECT_NEAR((w.wall.y0 + w.wall.y1) / 2, -0.05, 0.01) << seed;
			EXPECT_GT(w.evidence.count(), 0u) << seed;
		}
	}
	// Without walls the same contacts are held by legs (the model has nothing else).
	const maps::LastingMap plain = wallRun(false, 1);
	EXPECT_TRUE(plain.state().walls().empty());
	EXPECT_GT(plain.state().legCount(), 3u);
}

TEST(WallMap, NoWallAcrossCellsTheWhiskersSweptAndNeverTouched)
{
	// Four spots 0.3 m apart on the line y = 0.05, each touched on its +y face, as collinear
	// legs are: one wall explains them all (without free space). The robot swept the floor
	// between the spots 20 times and touched nothing there: eq. 25 rules the wall out.
	model::SweptGrid grid(0.1);
	for (int32_t ix = -1; ix <= 10; ix++)
		for (const int32_t iy : {-1, 0})
			grid.set(ix, iy, ix >= 0 && ix % 3 == 0 ? model::SweptGrid::Cell{0, 20} : model::SweptGrid::Cell{20, 0});
	const auto run = [&](bool freeSpace)
	{
		model::ModelParams p;
		p.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
		p.walls = true;
		p.free_space = freeSpace;
		const inference::SamplerParams s;
		maps::LastingMap m;
		std::mt19937_64 rng(7);
		std::normal_distribution<double> n(0, 1);
		for (int k = 0; k < 40; k++)
		{
			std::vector<obs::Shapelet> sweep;
			for (const int spot : {k % 4, (k + 1) % 4})
			{
				obs::Shapelet c;
				c.x = 0.3 * spot + 0.05 + 0.003 * n(rng), c.y = 0.05 + 0.003 * n(rng);
				c.normal = M_PI_2 + 0.05 * n(rng), c.texture = 0.3 + 0.02 * n(rng);
				sweep.push_back(c);
			}
			m.insert(sweep, p, s, 1000 + static_cast<uint64_t>(k), &grid);
		}
		double length = 0;
		for (const auto& w : m.state().walls())
			if (w.existence >= 0.5) length += w.wall.length();
		return length;
	};
	EXPECT_GT(run(false), 0.55);  // the grid is ignored: a wall from spot to spot (3 of the 4)
	EXPECT_LT(run(true), 0.2);  // at most a wall within one spot's touched cells
}

TEST(WallMap, SerializationKeepsTheWallsAndContinues)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/office/default.rawlog");
	maps::CHierarchicalObjectMap a;
	a.modelParams.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
	a.modelParams.walls = true;
	const size_t half = std::min<size_t>(rawlog.sweeps.size() / 2, 600);
	for (size_t i = 0; i < half; i++) a.insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	ASSERT_FALSE(a.lastingMap().state().walls().empty());
	const auto b = reloaded(a);
	ASSERT_TRUE(b);
	EXPECT_EQ(b->modelParams, a.modelParams);
	const auto same = [](const maps::CHierarchicalObjectMap& x, const maps::CHierarchicalObjectMap& y) {
		const auto &u = x.lastingMap().state().walls(), &v = y.lastingMap().state().walls();
		if (u.size() != v.size()) return false;
		for (size_t i = 0; i < u.size(); i++)
			if (u[i].wall.x0 != v[i].wall.x0 || u[i].wall.y1 != v[i].wall.y1 || u[i].existence != v[i].existence ||
				!(u[i].evidence == v[i].evidence))
				return false;
		return x.lastingMap().state().tableCount() == y.lastingMap().state().tableCount();
	};
	EXPECT_TRUE(same(a, *b));
	for (size_t i = half; i < half + 60 && i < rawlog.sweeps.size(); i++)
		for (auto* m : {&a, b.get()}) m->insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	EXPECT_TRUE(same(a, *b));
}

TEST(WallMap, VersionNineStreamsLoadTheWallsWithoutEndCapCosts)
{
	// Version 10 appends to each wall's folded evidence the frozen cost of its end caps'
	// contacts; a version 9 stream (the same bytes without it) loads with that cost 0.
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/office/default.rawlog");
	maps::CHierarchicalObjectMap a;
	a.modelParams.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
	a.modelParams.walls = true;
	for (size_t i = 0; i < std::min<size_t>(rawlog.sweeps.size(), 400); i++)
		a.insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	const auto& walls = a.lastingMap().state().walls();
	ASSERT_FALSE(walls.empty());
	mrpt::io::CMemoryStream buf;
	mrpt::serialization::archiveFrom(buf) << a;
	const auto* begin = static_cast<const uint8_t*>(buf.getRawBufferData());
	std::vector<uint8_t> bytes(begin, begin + buf.getTotalBytesCount());
	const std::string name = "whiskermap::maps::CHierarchicalObjectMap";
	ASSERT_EQ(bytes[1 + name.size()], maps::test::STREAM_VERSION);
	const std::vector<uint8_t> current = bytes;
	bytes[1 + name.size()] = 9;
	// version 11's tail (two spreads per class), version 12's (the batch: 16 bytes), version
	// 13's (three doubles per lasting table) and the later versions' (StreamTail.h), before
	// MRPT's end flag, go first
	const long spreads = 16 * static_cast<long>(a.modelParams.classes.size()), batch = 16,
			   chain = 24 * static_cast<long>(a.lastingMap().state().tableCount()) + maps::test::AFTER_CHAIN_SPREADS;
	bytes.erase(bytes.end() - 1 - spreads - batch - chain, bytes.end() - 1);
	bool first = true;
	for (const auto& w : walls)
	{
		// Each wall's record: x0, y0, x1, y1, thickness, texture, existence, the evidence's
		// STATS numbers (the last the caps' cost), its count.
		const double head[7] = {w.wall.x0, w.wall.y0, w.wall.x1, w.wall.y1, w.wall.thickness, w.wall.texture, w.existence};
		const auto* h = reinterpret_cast<const uint8_t*>(head);
		const auto at = std::search(bytes.begin(), bytes.end(), h, h + sizeof head);
		ASSERT_NE(at, bytes.end());
		const auto cap = at + static_cast<long>(sizeof head + 8 * model::WallEvidence::STATS_BEFORE_CAPS);
		if (first)
		{
			// In the current stream, a cap cost that is not a number >= 0 is refused.
			const auto offset = cap - bytes.begin();
			for (const double corrupt : {std::nan(""), -1.0, std::numeric_limits<double>::infinity()})
			{
				std::vector<uint8_t> bad = current;
				std::memcpy(bad.data() + offset, &corrupt, sizeof corrupt);
				mrpt::io::CMemoryStream in;
				in.assignMemoryNotOwn(bad.data(), bad.size());
				EXPECT_ANY_THROW(mrpt::serialization::archiveFrom(in).ReadObject()) << corrupt;
			}
			first = false;
		}
		bytes.erase(cap, cap + 8);
	}
	mrpt::io::CMemoryStream old;
	old.assignMemoryNotOwn(bytes.data(), bytes.size());
	const auto b = std::dynamic_pointer_cast<maps::CHierarchicalObjectMap>(mrpt::serialization::archiveFrom(old).ReadObject());
	ASSERT_TRUE(b);
	const auto& back = b->lastingMap().state().walls();
	ASSERT_EQ(back.size(), walls.size());
	for (size_t i = 0; i < walls.size(); i++)
	{
		EXPECT_TRUE(back[i].wall.sameAs(walls[i].wall, 0));
		auto expected = walls[i].evidence.stats();
		expected.back() = 0;
		EXPECT_EQ(back[i].evidence.stats(), expected) << i;
		EXPECT_EQ(back[i].evidence.count(), walls[i].evidence.count());
	}
}

TEST(WallMap, MappedWallsAreSolidsTheSweepLikelihoodPredictsContactsOn)
{
	// The office's first sweeps, mapped with walls: the walls join the legs as the solids the
	// particle filters' sweep likelihood predicts contacts on, and on their own they tell the
	// true poses from poses 5 cm off.
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/office/default.rawlog");
	maps::CHierarchicalObjectMap m;
	m.modelParams.classes = model::ObjectCatalogue::load(SRC + "/config/objects.ini");
	m.modelParams.walls = true;
	const size_t n = std::min<size_t>(rawlog.sweeps.size(), 300);
	for (size_t i = 0; i < n; i++) m.insertObservation(*rawlog.sweeps[i].obs, mrpt::poses::CPose3D(rawlog.sweeps[i].robotPose));
	const auto walls = m.mapWalls();
	ASSERT_GE(walls.size(), 2u);
	const auto& solids = m.mappedSolids();
	ASSERT_EQ(solids.size(), 4 * m.mapTables().size() + walls.size());
	std::vector<world::Obstacle> wallSolids;
	for (const auto& s : solids)
		if (s.table < 0) wallSolids.push_back(s);
	ASSERT_EQ(wallSolids.size(), walls.size());
	for (size_t k = 0; k < walls.size(); k++)  // the slab: its centre and its extent
	{
		const auto& w = walls[k].wall;
		const Eigen::Vector2d c = (wallSolids[k].corners[0] + wallSolids[k].corners[2]) / 2;
		EXPECT_NEAR(c.x(), (w.x0 + w.x1) / 2, 1e-9);
		EXPECT_NEAR(c.y(), (w.y0 + w.y1) / 2, 1e-9);
		EXPECT_NEAR((wallSolids[k].corners[2] - wallSolids[k].corners[0]).norm(), std::hypot(w.length(), w.thickness), 1e-9);
	}
	const maps::SweepLikelihood::TOptions o;
	const auto sum = [&](const std::vector<world::Obstacle>& s, double dx, double dy) {
		double ll = 0;
		for (size_t i = 0; i < n; i++)
			ll += maps::SweepLikelihood::logLikelihood(
				*rawlog.sweeps[i].obs, rawlog.sweeps[i].robotPose + mrpt::poses::CPose2D(dx, dy, 0), s, o);
		return ll;
	};
	const double truth = sum(wallSolids, 0, 0);
	for (const auto& [dx, dy] : {std::pair{0.05, 0.0}, {-0.05, 0.0}, {0.0, 0.05}, {0.0, -0.05}})
		EXPECT_GT(truth, sum(wallSolids, dx, dy) + 10) << dx << " " << dy;
	EXPECT_EQ(sum({}, 0, 0), sum({}, 0.05, 0));  // without solids no pose is preferred
}
