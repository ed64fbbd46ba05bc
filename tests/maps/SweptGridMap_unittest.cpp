// The map's swept grid (issue 9): kept by both modes, bounded by the area explored, shared
// by copies, serialized (stream version 5; version 4 streams load without it), read strictly
// from the .ini, and used by the sweep likelihood (doc/map-plugin.md, eqs. L1-L5).
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/obs/RawlogReader.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "StreamTail.h"

using namespace whiskermap;
using maps::CHierarchicalObjectMap;
using namespace maps::test;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

const obs::RawlogReader::Contents& arena()
{
	static const auto r = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	return r;
}

void insert(CHierarchicalObjectMap& m, size_t from, size_t to)
{
	for (size_t i = from; i < to && i < arena().sweeps.size(); i++)
		m.insertObservation(*arena().sweeps[i].obs, mrpt::poses::CPose3D(arena().sweeps[i].robotPose));
}

std::vector<uint8_t> bytesOf(const CHierarchicalObjectMap& m)
{
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << m;
	const auto* p = static_cast<const uint8_t*>(buf.getRawBufferData());
	return {p, p + buf.getTotalBytesCount()};
}

std::shared_ptr<CHierarchicalObjectMap> read(const std::vector<uint8_t>& bytes)
{
	mrpt::io::CMemoryStream buf;
	buf.assignMemoryNotOwn(bytes.data(), bytes.size());
	auto arch = mrpt::serialization::archiveFrom(buf);
	return std::dynamic_pointer_cast<CHierarchicalObjectMap>(arch.ReadObject());
}

double score(const CHierarchicalObjectMap& m, size_t sweep, double dx = 0)
{
	const auto& s = arena().sweeps[sweep];
	return m.computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(s.robotPose + mrpt::poses::CPose2D(dx, 0, 0)));
}
}  // namespace

TEST(SweptGridMap, BothModesKeepItBoundedByTheArea)
{
	for (const auto mode : {CHierarchicalObjectMap::TInsertionOptions::TMode::Lasting,
							CHierarchicalObjectMap::TInsertionOptions::TMode::PerPose})
	{
		CHierarchicalObjectMap m;
		m.insertionOptions.mode = mode;
		m.insertionOptions.keep_history = false;
		insert(m, 0, 200);
		const size_t cells = m.sweptGrid().cells().size();
		EXPECT_GT(cells, 400u);  // 0.1 m cells of a 4 m x 4 m arena: at most about 2000
		EXPECT_LT(cells, 2500u);
		insert(m, 0, 200);  // the same sweeps again: no new cell, counts doubled
		EXPECT_EQ(m.sweptGrid().cells().size(), cells);
		m.clear();
		EXPECT_TRUE(m.sweptGrid().empty());
	}
}

TEST(SweptGridMap, CopiesShareTheGridAndStreamsKeepIt)
{
	CHierarchicalObjectMap a;
	a.likelihoodOptions.sweep.use_swept_grid = true;
	insert(a, 0, 150);
	CHierarchicalObjectMap b = a;  // as resampling copies
	EXPECT_EQ(b.sweptGrid().sharedChunks(), b.sweptGrid().chunkCount());
	insert(b, 150, 151);
	EXPECT_LT(b.sweptGrid().sharedChunks(), b.sweptGrid().chunkCount());
	EXPECT_FALSE(a.sweptGrid().empty());
	const auto back = read(bytesOf(a));
	ASSERT_TRUE(back);
	const auto ca = a.sweptGrid().cells(), cb = back->sweptGrid().cells();
	ASSERT_EQ(ca.size(), cb.size());
	for (size_t k = 0; k < ca.size(); k++)
	{
		EXPECT_EQ(ca[k].ix, cb[k].ix);
		EXPECT_EQ(ca[k].iy, cb[k].iy);
		EXPECT_EQ(ca[k].cell.passes, cb[k].cell.passes);
		EXPECT_EQ(ca[k].cell.touches, cb[k].cell.touches);
	}
	EXPECT_TRUE(back->likelihoodOptions.sweep.use_swept_grid);
	EXPECT_EQ(score(*back, 100, 0.2), score(a, 100, 0.2));
}

// A version 4 stream (the same bytes without version 5's tail, whose use_swept_grid is then
// the default, off) loads with an empty grid and scores as the likelihood without it.
TEST(SweptGridMap, VersionFourStreamsLoadWithoutTheGrid)
{
	CHierarchicalObjectMap a;
	a.likelihoodOptions.sweep.use_swept_grid = true;
	insert(a, 0, 150);
	auto bytes = bytesOf(a);
	const std::string name = "whiskermap::maps::CHierarchicalObjectMap";
	ASSERT_EQ(bytes[0], static_cast<uint8_t>(name.size() | 0x80));
	ASSERT_EQ(std::string(bytes.begin() + 1, bytes.begin() + 1 + static_cast<long>(name.size())), name);
	ASSERT_EQ(bytes[1 + name.size()], STREAM_VERSION);
	ASSERT_TRUE(a.lastingMap().state().walls().empty());  // version 10 changes only the walls' records
	ASSERT_TRUE(a.modelParams.classes.empty());  // version 11 adds 16 bytes per class: none here
	bytes[1 + name.size()] = 4;
	// version 5's tail: swept_cell, free_space, cell_prior, cell_prior_sweeps, p_unexplored,
	// the grid's cell edge and count, 12 bytes a cell; version 6's sigma_corner,
	// noisy_revisions and revision round robin's insertion number; version 7's move types
	// (a count, then per type a length byte, the name and two 8-byte counts); version 8's
	// size_moves and four size offsets per lasting table; version 9's sensor noise (three
	// doubles); version 12's batch (batch_sweeps, sweeps pending, first pending insertion
	// number: 16 bytes); version 13's chain pose spreads (three doubles per lasting table);
	// the later versions' tails (StreamTail.h); then MRPT's end flag
	size_t moveTypes = 4;
	for (const auto& t : a.moveTypes()) moveTypes += 1 + t.name.size() + 8 + 8;
	ASSERT_GT(a.moveTypes().size(), 5u);
	const size_t sizes = 1 + 32 * a.lastingMap().state().tableCount();
	const size_t tail = 8 + 1 + 8 + 8 + 8 + 8 + 4 + 12 * a.sweptGrid().cells().size() + 8 + 4 + 8 + moveTypes + sizes + 24 + 16 +
						24 * a.lastingMap().state().tableCount() + AFTER_CHAIN_SPREADS;
	bytes.erase(bytes.end() - 1 - static_cast<long>(tail), bytes.end() - 1);
	const auto old = read(bytes);
	ASSERT_TRUE(old);
	EXPECT_TRUE(old->sweptGrid().empty());
	EXPECT_EQ(old->mapObjects().size(), a.mapObjects().size());
	CHierarchicalObjectMap legacy = a;
	legacy.likelihoodOptions.sweep.use_swept_grid = false;
	for (const double dx : {0.0, 0.3})
	{
		EXPECT_EQ(score(*old, 120, dx), score(legacy, 120, dx));
		EXPECT_NE(score(a, 120, dx), score(legacy, 120, dx));  // the grid does change the score
	}
}

// insertOpts record_swept = false (a particle filter's maps: whisker-slam): the grid stays
// empty and nothing else changes; version 15 stores the key (older streams record); and the
// key cannot be off while the likelihood (use_swept_grid) or the model (free_space) reads it.
TEST(SweptGridMap, UnrecordedItStaysEmptyAndTheMapIsTheSame)
{
	CHierarchicalObjectMap a, b;
	b.insertionOptions.record_swept = false;
	insert(a, 0, 150);
	insert(b, 0, 150);
	EXPECT_FALSE(a.sweptGrid().empty());
	EXPECT_TRUE(b.sweptGrid().empty());
	const auto ta = a.mapTables(), tb = b.mapTables();
	ASSERT_EQ(ta.size(), tb.size());
	ASSERT_GT(ta.size(), 0u);
	for (size_t k = 0; k < ta.size(); k++)
	{
		EXPECT_EQ(ta[k].x, tb[k].x);
		EXPECT_EQ(ta[k].y, tb[k].y);
		EXPECT_EQ(ta[k].yaw, tb[k].yaw);
	}
	for (const double dx : {0.0, 0.3}) EXPECT_EQ(score(a, 120, dx), score(b, 120, dx));

	std::vector<uint8_t> bytes = bytesOf(b);
	const auto back = read(bytes);
	ASSERT_TRUE(back);
	EXPECT_FALSE(back->insertionOptions.record_swept);
	const std::string name = "whiskermap::maps::CHierarchicalObjectMap";
	ASSERT_EQ(bytes[1 + name.size()], STREAM_VERSION);
	bytes[1 + name.size()] = 14;
	bytes.erase(bytes.end() - 1 - AFTER_MANHATTAN, bytes.end() - 1);
	const auto old = read(bytes);
	ASSERT_TRUE(old);
	EXPECT_TRUE(old->insertionOptions.record_swept);

	std::ifstream in(SRC + "/config/whisker-map.ini");
	const std::string shipped((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	const std::string path = (std::filesystem::temp_directory_path() / "whiskermap_record_swept.ini").string();
	// The shipped config with each (key line, its replacement) applied.
	const auto load = [&](const std::vector<std::pair<std::string, std::string>>& edits) {
		std::string text = shipped;
		for (const auto& [from, to] : edits)
		{
			const size_t at = text.find(from);
			EXPECT_NE(at, std::string::npos) << from;
			text.replace(at, from.size(), to);
		}
		std::ofstream(path) << text;
		return maps::MapConfig::load(path);
	};
	const std::string insertOpts = "[MetricMap_hierarchicalObjectMap_00_insertOpts]\n";
	const std::string likelihoodOpts = "[MetricMap_hierarchicalObjectMap_00_likelihoodOpts]\n";
	const std::pair<std::string, std::string> unrecorded{insertOpts, insertOpts + "record_swept = false\n"};
	const auto m = mrpt::maps::CMultiMetricMap(load({unrecorded})).mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(m);
	EXPECT_FALSE(m->insertionOptions.record_swept);
	EXPECT_THROW(load({{insertOpts, insertOpts + "record_swept = maybe\n"}}), core::Error);
	EXPECT_THROW(load({unrecorded, {likelihoodOpts, likelihoodOpts + "use_swept_grid = true\n"}}), core::Error);
	EXPECT_THROW(load({unrecorded, {"free_space = false", "free_space = true"}}), core::Error);
	EXPECT_NO_THROW(load({{"free_space = false", "free_space = true"}}));
	std::filesystem::remove(path);
}

TEST(SweptGridMap, OptionsAreReadStrictly)
{
	const auto path = (std::filesystem::temp_directory_path() / ("whiskermap_swept_" + std::to_string(::getpid()) + ".ini")).string();
	const auto load = [&](const std::string& likelihood, const std::string& insert) {
		std::ofstream(path) << "[MetricMap]\nhierarchicalObjectMap_count=1\n"
							<< "[MetricMap_hierarchicalObjectMap_00_likelihoodOpts]\n" << likelihood
							<< "[MetricMap_hierarchicalObjectMap_00_insertOpts]\n" << insert;
		return maps::MapConfig::load(path);
	};
	const auto good = load("use_swept_grid=true\ncell_prior=0.2\ncell_prior_sweeps=3\np_unexplored=0.01\n", "swept_cell=0.2\n");
	const auto m = mrpt::maps::CMultiMetricMap(good).mapByClass<CHierarchicalObjectMap>();
	ASSERT_TRUE(m);
	EXPECT_TRUE(m->likelihoodOptions.sweep.use_swept_grid);
	EXPECT_EQ(m->likelihoodOptions.sweep.cell_prior, 0.2);
	EXPECT_EQ(m->likelihoodOptions.sweep.cell_prior_sweeps, 3);
	EXPECT_EQ(m->likelihoodOptions.sweep.p_unexplored, 0.01);
	EXPECT_EQ(m->insertionOptions.swept_cell, 0.2);
	EXPECT_THROW(load("cell_prior=1\n", ""), core::Error);
	EXPECT_THROW(load("p_unexplored=0\n", ""), core::Error);
	EXPECT_THROW(load("use_swept_grid=maybe\n", ""), core::Error);
	EXPECT_THROW(load("", "swept_cell=0\n"), core::Error);
	std::filesystem::remove(path);
}

// Version 7's counts per move type: they add up to the counts per kind of move, survive a
// round trip, and a corrupt count (more types than any registry holds, or more acceptances
// than proposals) is refused with an error, not an allocation.
TEST(SweptGridMap, MoveTypeCountsAddUpAndAreReadStrictly)
{
	for (const bool perPose : {false, true})
	{
		CHierarchicalObjectMap a;
		if (perPose) a.insertionOptions.mode = CHierarchicalObjectMap::TInsertionOptions::TMode::PerPose;
		insert(a, 0, 60);
		uint64_t proposed = 0, accepted = 0, byType = 0, acceptedByType = 0;
		for (size_t k = 0; k < inference::MOVE_COUNT; k++) proposed += a.proposed()[k], accepted += a.accepted()[k];
		for (const auto& t : a.moveTypes()) byType += t.proposed, acceptedByType += t.accepted;
		EXPECT_GT(proposed, 100u);
		EXPECT_EQ(byType, proposed) << perPose;
		EXPECT_EQ(acceptedByType, accepted) << perPose;
		ASSERT_FALSE(a.moveTypes().empty());
		EXPECT_EQ(a.moveTypes().front().name, "priming");
		const auto back = read(bytesOf(a));
		ASSERT_TRUE(back);
		ASSERT_EQ(back->moveTypes().size(), a.moveTypes().size());
		EXPECT_EQ(back->moveTypes().back().name, a.moveTypes().back().name);
		EXPECT_EQ(back->moveTypes().back().accepted, a.moveTypes().back().accepted);
	}
	CHierarchicalObjectMap a;
	insert(a, 0, 30);
	size_t section = 4;
	for (const auto& t : a.moveTypes()) section += 1 + t.name.size() + 8 + 8;
	const std::vector<uint8_t> good = bytesOf(a);
	const size_t sizes = 1 + 56 * a.lastingMap().state().tableCount() + 24 + 16 + AFTER_CHAIN_SPREADS;  // versions 8, 9, 12, 13 and later, after it
	const size_t at = good.size() - 1 - sizes - section;  // the section's type count
	std::vector<uint8_t> bad = good;
	bad[at] = 65, bad[at + 1] = bad[at + 2] = bad[at + 3] = 0;  // little-endian 65
	EXPECT_THROW(read(bad), std::exception);
	bad = good;
	const size_t lastAccepted = good.size() - 1 - sizes - 8;
	bad[lastAccepted + 7] = 0x7f;  // the last type's acceptances far above its proposals
	EXPECT_THROW(read(bad), std::exception);
	EXPECT_TRUE(read(good));
}

// Version 8: size moves and each lasting table's size offsets survive a round trip; a
// non-finite offset is refused.
TEST(SweptGridMap, TableSizesRoundTripAndAreReadStrictly)
{
	CHierarchicalObjectMap a;
	model::ObjectClass table;  // the paper arena's table as the one class
	a.modelParams.classes = {table};
	a.modelParams.size_moves = true;
	insert(a, 0, 200);
	const auto& s = a.lastingMap().state();
	ASSERT_GT(s.tableCount(), 0u);
	bool resized = false;
	for (model::Id t = 0; t < s.tableIdBound(); t++)
		if (s.hasTable(t)) resized |= s.table(t).d_length != 0;
	EXPECT_TRUE(resized);  // the arena's tables are the class's size; their fits move by noise
	const std::vector<uint8_t> good = bytesOf(a);
	const auto back = read(good);
	ASSERT_TRUE(back);
	EXPECT_TRUE(back->modelParams.size_moves);
	const auto& r = back->lastingMap().state();
	ASSERT_EQ(r.tableCount(), s.tableCount());
	for (model::Id t = 0, u = 0; t < s.tableIdBound(); t++)
	{
		if (!s.hasTable(t)) continue;
		while (!r.hasTable(u)) u++;
		EXPECT_EQ(r.table(u).d_length, s.table(t).d_length);
		EXPECT_EQ(r.table(u).d_width, s.table(t).d_width);
		EXPECT_EQ(r.reported(u).d_width, s.reported(t).d_width);
		u++;
	}
	ASSERT_EQ(back->mapTables().size(), a.mapTables().size());
	for (size_t i = 0; i < a.mapTables().size(); i++) EXPECT_EQ(back->mapTables()[i].length, a.mapTables()[i].length);
	std::vector<uint8_t> bad = good;
	const double nan = std::nan("");
	// The last table's reported width offset; after it version 9's sensor noise (24 bytes),
	// version 11's spreads of the one class (16), version 12's batch (16), version 13's chain
	// spreads (24 a table), the later versions' tails and MRPT's end flag.
	std::memcpy(&bad[bad.size() - 1 - AFTER_CHAIN_SPREADS - 24 * s.tableCount() - 16 - 16 - 24 - 8], &nan, 8);
	EXPECT_THROW(read(bad), std::exception);
}

// Version 9: the last insertion's sensor noise survives a round trip, so a reloaded map
// reports the same pose spreads; a negative or non-finite noise is refused.
TEST(SweptGridMap, SensorNoiseRoundTripsAndThePoseSpreadsWithIt)
{
	// The very noisy log states a sigma_r above the model's: the spreads' model is raised to it.
	static const auto noisy = obs::RawlogReader::read(SRC + "/datasets/paper_arena/very-noisy.rawlog");
	CHierarchicalObjectMap a, base;
	for (size_t i = 0; i < 200; i++)
		a.insertObservation(*noisy.sweeps[i].obs, mrpt::poses::CPose3D(noisy.sweeps[i].robotPose));
	ASSERT_GT(noisy.sweeps[0].obs->noise.sigma_r, a.modelParams.sigma_r);
	const auto spreads = a.mapObjects(true);
	ASSERT_FALSE(spreads.empty());
	const std::vector<uint8_t> good = bytesOf(a);
	const auto back = read(good);
	ASSERT_TRUE(back);
	const auto again = back->mapObjects(true);
	ASSERT_EQ(again.size(), spreads.size());
	// Equal up to the order of summation (a reloaded state lists a leg's contacts anew).
	for (size_t i = 0; i < spreads.size(); i++)
	{
		EXPECT_GT(spreads[i].sd_x, 0);
		EXPECT_NEAR(again[i].sd_x, spreads[i].sd_x, 1e-6 * spreads[i].sd_x);
		EXPECT_NEAR(again[i].sd_yaw, spreads[i].sd_yaw, 1e-6 * spreads[i].sd_yaw);
	}
	back->insertionOptions.use_sensor_noise = false;  // the map's own sigma_r: narrower spreads
	const auto narrow = back->mapObjects(true);
	for (size_t i = 0; i < spreads.size(); i++) EXPECT_LT(narrow[i].sd_x, spreads[i].sd_x) << i;
	for (const double v : {-0.01, std::nan(""), 1e9})
	{
		std::vector<uint8_t> bad = good;
		// sigma_r, the first of version 9's three doubles; after them version 11's spreads (no
		// class here), version 12's batch (16 bytes), version 13's chain spreads (24 a table),
		// the later versions' tails and MRPT's end flag.
		ASSERT_TRUE(a.modelParams.classes.empty());
		std::memcpy(&bad[bad.size() - 1 - AFTER_CHAIN_SPREADS - 24 * a.lastingMap().state().tableCount() - 16 - 24], &v, 8);
		EXPECT_THROW(read(bad), std::exception) << v;
	}
}
