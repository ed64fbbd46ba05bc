// whisker-insert-bench: the time of each insertion into a CHierarchicalObjectMap (lasting mode
// by default), over a whole rawlog, as a distribution: median, p95, max and mean wall time and
// thread CPU time per sweep, the map's size at the end, the time and heap of a copy of it (the two ways
// a particle filter's resampling may copy it) and the process's peak RSS. The sweeps
// are streamed (one in memory at a time). --repeat N maps the log N times and adds, per
// insertion, the least time over the runs (the uncontended estimate). Figures and commands: doc/benchmarks.md, "Lasting
// map: insertion time and scaling" (scripts/bench-lasting.sh).
#include <CLI/CLI.hpp>
#include <mrpt/maps/CMultiMetricMap.h>
#include <sys/resource.h>
#include <whiskermap/cli/runApp.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/heapInUseMb.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/maps/MapConfig.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numeric>
#include <vector>

using namespace whiskermap;

namespace
{
double threadCpuMs()
{
	timespec t{};
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

/** The q-quantile (nearest rank) of sorted values. */
double quantile(const std::vector<double>& sorted, double q)
{
	const size_t i = static_cast<size_t>(std::ceil(q * static_cast<double>(sorted.size())));
	return sorted[std::min(sorted.size() - 1, i == 0 ? 0 : i - 1)];
}

void report(const char* what, std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	const double mean = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
	std::printf(
		"  %s ms per insertion: median %.4f, p95 %.4f, max %.4f, mean %.4f\n", what, quantile(v, 0.5),
		quantile(v, 0.95), v.back(), mean);
}

struct Times
{
	std::vector<double> wall, cpu;  ///< ms per insertion, in the log's order
};

/** Maps the whole rawlog into a new map from `config` (mode overridden unless empty), timing
 *  every insertion, and prints the run's report. */
Times mapOnce(const std::string& config, const std::string& mode, const std::string& rawlog)
{
	mrpt::maps::CMultiMetricMap mm(maps::MapConfig::load(config));
	auto map = mm.mapByClass<maps::CHierarchicalObjectMap>();
	if (!map) throw core::Error(config + ": no hierarchicalObjectMap in [MetricMap]");
	map->insertionOptions.keep_history = false;  // as whisker-map: memory bounded by the map
	using Mode = maps::CHierarchicalObjectMap::TInsertionOptions::TMode;
	if (!mode.empty()) map->insertionOptions.mode = mode == "lasting" ? Mode::Lasting : Mode::PerPose;
	obs::RawlogReader reader(rawlog);
	Times t;
	t.wall.reserve(reader.summary().sweepCount), t.cpu.reserve(reader.summary().sweepCount);
	obs::RawlogReader::Sweep s;
	while (reader.next(s))
	{
		const mrpt::poses::CPose3D pose(s.robotPose);
		const double c0 = threadCpuMs();
		const auto t0 = std::chrono::steady_clock::now();
		map->insertObservation(*s.obs, pose);
		t.wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
		t.cpu.push_back(threadCpuMs() - c0);
	}
	if (t.wall.empty()) throw core::Error(rawlog + ": no whisker sweeps");
	rusage usage{};
	getrusage(RUSAGE_SELF, &usage);
	std::printf(
		"%s (%s): %zu insertions, %zu map objects, peak RSS %.1f MB\n", rawlog.c_str(),
		map->lasting() ? "lasting" : "per_pose", t.wall.size(), map->mapObjects().size(),
		static_cast<double>(usage.ru_maxrss) / 1024.0);
	report("wall", t.wall);
	report("cpu ", t.cpu);
	{
		// A copy of the map as the log left it, two ways: MRPT's CMultiMetricMap copy (a
		// serialization round trip of every map: CMultiMetricMapPDF's own resampling) and the
		// map's copy constructor (whisker-slam's resampling clones the maps: RbpfSlam::resample).
		const auto timed = [](const auto& copyOnce)
		{
			std::vector<double> v;
			for (int k = 0; k < 51; k++)
			{
				const auto t0 = std::chrono::steady_clock::now();
				copyOnce();
				v.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
			}
			std::sort(v.begin(), v.end());
			return quantile(v, 0.5);
		};
		const double serialized = timed([&] { const mrpt::maps::CMultiMetricMap copy(mm); });
		size_t shared = 0;
		const double cloned = timed([&] {
			const maps::CHierarchicalObjectMap copy(*map);
			shared = map->sweptGrid().sharedChunks();
		});
		// What a copy adds to the heap (its share of ten copies kept at once; NaN under ASan).
		const double before = core::heapInUseMb();
		const std::vector<maps::CHierarchicalObjectMap> copies(10, *map);
		const double heapKb = (core::heapInUseMb() - before) / 10 * 1024;
		const auto lasting = copies[0].lastingMap().state().sharing();
		std::printf(
			"map copy, median of 51: %.3f ms as MRPT's CMultiMetricMap copy (serialized), %.3f ms by the copy "
			"constructor (swept grid chunks shared: %zu of %zu; lasting state: %zu of %zu), %.1f kB of heap a copy\n",
			serialized, cloned, shared, map->sweptGrid().chunkCount(), lasting.shared, lasting.chunks, heapKb);
	}
	if (map->lasting())  // the outputs' pose spreads (a chain per object, doc/map-plugin.md)
	{
		const auto t0 = std::chrono::steady_clock::now();
		const size_t n = map->mapObjects(true).size() + map->candidateObjects(true).size();
		const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
		std::printf("pose spreads: %zu objects in %.1f ms (%.2f ms each)\n", n, ms, n ? ms / n : 0.0);
	}
	return t;
}
}  // namespace

int main(int argc, char** argv)
{
	CLI::App app{"Times every insertion of a rawlog's sweeps into a CHierarchicalObjectMap"};
	std::string rawlog, config = WHISKERMAP_SOURCE_DIR "/config/whisker-map.ini", mode;
	unsigned repeat = 1;
	app.add_option("rawlog", rawlog, "Rawlog of whisker sweeps (whisker-sim's output)")->required();
	app.add_option("-c,--config", config, "Map configuration (default: the shipped config/whisker-map.ini)");
	app.add_option("--mode", mode, "Override the map's mode: lasting or per_pose")
		->check(CLI::IsMember({"lasting", "per_pose"}));
	app.add_option(
		   "--repeat", repeat,
		   "Map the rawlog this many times, each into a new map (the same work: the same seed gives the same map), "
		   "and report each run, then per insertion the least time over the runs: other load on the machine only "
		   "adds time, so that is the estimate for an uncontended core")
		->check(CLI::Range(1u, 1000u));
	return cli::runApp(app, argc, argv, "whisker-insert-bench", [&] {
		std::vector<double> leastWall, leastCpu;
		for (unsigned run = 0; run < repeat; run++)
		{
			const Times t = mapOnce(config, mode, rawlog);
			if (run == 0) leastWall = t.wall, leastCpu = t.cpu;
			for (size_t i = 0; i < t.wall.size(); i++)
				leastWall[i] = std::min(leastWall[i], t.wall[i]), leastCpu[i] = std::min(leastCpu[i], t.cpu[i]);
		}
		if (repeat > 1)
		{
			std::printf("least of %u runs, per insertion:\n", repeat);
			report("wall", leastWall);
			report("cpu ", leastCpu);
		}
		return 0;
	});
}
