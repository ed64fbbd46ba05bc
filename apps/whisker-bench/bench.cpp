// whisker-bench: Google Benchmark figures for the costs a particle filter pays per particle:
// inserting one whisker sweep into a CHierarchicalObjectMap (one sampler step) and
// scoring one sweep against a built map. Data: the shipped paper-arena datasets
// ($WHISKERMAP_DATA_DIR, default the source tree's datasets/paper_arena).
// Run: whisker-bench [--benchmark_filter=...] ; figures and commands in doc/benchmarks.md.
#include <benchmark/benchmark.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/obs/RawlogReader.h>

#include <cstdlib>
#include <map>

using namespace whiskermap;

namespace
{
std::string dataDir()
{
	const char* env = std::getenv("WHISKERMAP_DATA_DIR");
	return env ? env : WHISKERMAP_SOURCE_DIR "/datasets/paper_arena";
}

const obs::RawlogReader::Contents& dataset(const std::string& name)
{
	static std::map<std::string, obs::RawlogReader::Contents> cache;
	auto it = cache.find(name);
	if (it == cache.end()) it = cache.emplace(name, obs::RawlogReader::read(dataDir() + "/" + name + ".rawlog")).first;
	return it->second;
}

std::unique_ptr<mrpt::maps::CMultiMetricMap> newMap()
{
	return std::make_unique<mrpt::maps::CMultiMetricMap>(
		maps::MapConfig::load(WHISKERMAP_SOURCE_DIR "/config/whisker-map.ini"));
}

/** One sweep inserted: a sampler step plus consolidation (the map keeps no history). */
void BM_InsertSweep(benchmark::State& state, const std::string& name)
{
	const auto& sweeps = dataset(name).sweeps;
	auto mm = newMap();
	mm->mapByClass<maps::CHierarchicalObjectMap>()->insertionOptions.keep_history = false;
	size_t i = 0;
	for (auto _ : state)
	{
		const auto& s = sweeps[i++ % sweeps.size()];
		mm->insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
	}
	state.SetItemsProcessed(state.iterations());
}

/** The map built from the whole dataset (keeping no history, as a particle's map). */
std::unique_ptr<mrpt::maps::CMultiMetricMap> builtMap(const std::string& name, bool freeSpace)
{
	auto mm = newMap();
	auto* m = mm->mapByClass<maps::CHierarchicalObjectMap>().get();
	m->insertionOptions.keep_history = false;
	m->likelihoodOptions.sweep.use_swept_grid = freeSpace;
	for (const auto& s : dataset(name).sweeps) mm->insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
	return mm;
}

/** One sweep scored against the map built from the whole dataset (a particle's weight);
 *  `freeSpace`: with the swept grid's eqs. L1-L5. */
void BM_SweepLikelihood(benchmark::State& state, const std::string& name, bool freeSpace)
{
	const auto& sweeps = dataset(name).sweeps;
	auto mm = builtMap(name, freeSpace);
	size_t i = 0;
	double sink = 0;
	for (auto _ : state)
	{
		const auto& s = sweeps[i++ % sweeps.size()];
		sink += mm->computeObservationLikelihood(*s.obs, mrpt::poses::CPose3D(s.robotPose));
	}
	benchmark::DoNotOptimize(sink);
	state.SetItemsProcessed(state.iterations());
}

/** A copy of the map built from the whole dataset, as resampling makes; `gridOnly`: its
 *  swept grid alone (shared chunks). */
void BM_MapCopy(benchmark::State& state, bool gridOnly)
{
	auto mm = builtMap("default", true);
	const auto& m = *mm->mapByClass<maps::CHierarchicalObjectMap>();
	for (auto _ : state)
	{
		if (gridOnly)
		{
			model::SweptGrid copy = m.sweptGrid();
			benchmark::DoNotOptimize(copy);
		}
		else
		{
			maps::CHierarchicalObjectMap copy = m;
			benchmark::DoNotOptimize(copy);
		}
	}
	state.SetItemsProcessed(state.iterations());
	state.counters["grid_chunks"] = static_cast<double>(m.sweptGrid().chunkCount());
	state.counters["grid_cells"] = static_cast<double>(m.sweptGrid().cells().size());
}
}  // namespace

BENCHMARK_CAPTURE(BM_InsertSweep, noiseless, std::string("noiseless"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_InsertSweep, default, std::string("default"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_InsertSweep, very_noisy, std::string("very-noisy"))->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SweepLikelihood, default, std::string("default"), true)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SweepLikelihood, default_no_free_space, std::string("default"), false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_MapCopy, whole_map, false)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_MapCopy, swept_grid_only, true)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
