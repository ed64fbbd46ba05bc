// Does the sampler find the MAP? Its log posterior against the exact oracle's on a few
// hundred single time steps: working memories replayed from the shipped paper-arena rawlogs,
// and random contacts on random tables (doc/oracle.md).
#include <gtest/gtest.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/ExactMapOracle.h>
#include <whiskermap/inference/ShapeletMemory.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>

#include "SyntheticTable.h"

using namespace whiskermap;
using inference::BlackboardSampler;
using inference::ExactMapOracle;
using inference::SamplerParams;
using model::ModelParams;

namespace
{
const ModelParams P;

/** The sampler "agrees" when its MAP is at most this far below the oracle's: below the
 *  smallest structural difference (an invented vs a missing leg, 1.7 nats). */
constexpr double AGREEMENT_NATS = 1.0;
/** The sampler may beat the oracle by the grid's effect (1 cm, 1 deg tables: doc/oracle.md);
 *  more than this would mean the oracle missed a configuration. */
constexpr double GRID_NATS = 2.0;

struct Problem
{
	std::string source;
	std::vector<obs::Shapelet> shapelets;
};

/** Every `stride`-th working memory (N = 7) of a rawlog, as the map would feed the sampler. */
void fromRawlog(const std::string& name, size_t stride, std::vector<Problem>& out)
{
	const auto log = obs::RawlogReader::read(std::string(WHISKERMAP_SOURCE_DIR) + "/datasets/paper_arena/" + name);
	inference::ShapeletMemory memory;
	for (size_t i = 0; i < log.sweeps.size(); i++)
	{
		memory.add(log.sweeps[i].obs->toShapelets(log.sweeps[i].robotPose));
		if (i % stride == 0 && memory.shapelets().size() >= 2) out.push_back({name + " pose " + std::to_string(i), memory.shapelets()});
	}
}

/** Random contacts on one or two random tables (1-4 legs, 1-2 faces each, noise as the
 *  default sensor), sometimes a stray contact (a wall); the last 7 kept. */
void synthetic(size_t count, std::vector<Problem>& out)
{
	std::mt19937_64 rng(20110831);
	const auto uniform = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
	const auto gaussian = [&] { return std::sqrt(-2 * std::log(1 - uniform())) * std::cos(2 * M_PI * uniform()); };
	for (size_t k = 0; k < count; k++)
	{
		std::vector<obs::Shapelet> s;
		const int tables = uniform() < 0.25 ? 2 : 1;
		for (int t = 0; t < tables; t++)
		{
			const model::Table table{
				4 * uniform() - 2 + 1.6 * t, 4 * uniform() - 2, M_PI * uniform(), P.leg_width, P.texture};
			std::vector<test::Touch> touches;
			const int legs = 1 + static_cast<int>(4 * uniform());
			for (int l = 0; l < legs; l++)
				for (int f = 0, faces = uniform() < 0.4 ? 2 : 1; f < faces; f++)
					touches.push_back({(l + t) % 4, static_cast<int>(4 * uniform()), (uniform() - 0.5) * P.leg_width});
			for (obs::Shapelet c : test::touchTable(table, P, touches))
			{
				c.x += 0.003 * gaussian(), c.y += 0.003 * gaussian();
				c.normal += 0.03 * gaussian(), c.texture += 0.02 * gaussian();
				s.push_back(c);
			}
		}
		if (uniform() < 0.2) s.push_back({s[0].x + 0.5 * uniform(), s[0].y - 0.5, M_PI_2, 0.9, 0});
		if (s.size() > 7) s.erase(s.begin(), s.end() - 7);
		out.push_back({"synthetic " + std::to_string(k), s});
	}
}

double median(std::vector<double> v)
{
	std::sort(v.begin(), v.end());
	return v[v.size() / 2];
}

/** With WHISKERMAP_AGREEMENT_DUMP set, a failing problem's shapelets and both maps. */
void dump(const std::vector<obs::Shapelet>& s, const model::HypothesisSet& o, const model::HypothesisSet& m)
{
	for (size_t i = 0; i < s.size(); i++)
		std::printf("      S%zu (%7.3f %7.3f) n %6.1f deg tex %.2f: oracle leg %d, sampler leg %d\n", i, s[i].x, s[i].y,
					s[i].normal * 180 / M_PI, s[i].texture, o.shapeletParent[i], m.shapeletParent[i]);
	for (const auto* h : {&o, &m})
		for (size_t i = 0; i < h->legs.size(); i++)
			std::printf("      %s leg %zu (%7.3f %7.3f) yaw %6.1f table %d\n", h == &o ? "oracle " : "sampler", i,
						h->legs[i].x, h->legs[i].y, h->legs[i].theta * 180 / M_PI, h->legs[i].parent);
}

template <class F>
double seconds(F&& f)
{
	const auto t0 = std::chrono::steady_clock::now();
	f();
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

/** Measured 98.5% (256/260) with the polish's sliding table and contact exchange (95.4%
 *  before them, 88.1% before the shared leg pose search, 13.5% before any pose move); floor
 *  with a margin. */
constexpr double MIN_AGREEMENT_PERCENT = 95.0;

TEST(OracleAgreement, SamplerFindsTheExactMap)
{
	std::vector<Problem> problems;
	fromRawlog("default.rawlog", 5, problems);
	fromRawlog("noiseless.rawlog", 5, problems);
	synthetic(100, problems);
	ASSERT_GE(problems.size(), 200u);

	// Two workers (the oracle is const; one sampler each); seeds depend only on the problem.
	struct Outcome
	{
		inference::StepResult sampler;
		inference::OracleResult oracle;
		double samplerSeconds, oracleSeconds;
	};
	std::vector<Outcome> out(problems.size());
	const ExactMapOracle oracle(P);
	// WHISKERMAP_AGREEMENT_ACCEPTANCE=reversible_jump measures the other acceptance rule
	// (doc/sampler.md); the regression floor holds for the default rule only.
	SamplerParams params;
	const char* rule = std::getenv("WHISKERMAP_AGREEMENT_ACCEPTANCE");
	if (rule && std::string(rule) == "reversible_jump") params.acceptance = inference::AcceptanceRule::ReversibleJump;
	ASSERT_TRUE(!rule || std::string(rule) == "gibbs" || std::string(rule) == "reversible_jump") << rule;
	const auto work = [&](size_t first) {
		BlackboardSampler sampler(P, params);
		for (size_t i = first; i < problems.size(); i += 2)
		{
			out[i].samplerSeconds = seconds([&] { out[i].sampler = sampler.step(problems[i].shapelets, i); });
			out[i].oracleSeconds = seconds([&] { out[i].oracle = oracle.solve(problems[i].shapelets); });
		}
	};
	std::thread other(work, 1);
	work(0);
	other.join();

	double maxAbove = -1e9;
	size_t agree = 0, above = 0, missedTable = 0, extraTable = 0, sameTables = 0, within5 = 0, within10 = 0;
	std::vector<double> samplerTimes, oracleTimes;
	for (size_t i = 0; i < problems.size(); i++)
	{
		const auto& s = out[i].sampler;
		const auto& o = out[i].oracle;
		samplerTimes.push_back(out[i].samplerSeconds);
		oracleTimes.push_back(out[i].oracleSeconds);
		EXPECT_TRUE(o.certified) << problems[i].source;
		const double below = o.logPosterior - s.logPosterior;
		agree += below <= AGREEMENT_NATS;
		within5 += below <= 5, within10 += below <= 10;
		above += -below > GRID_NATS;
		maxAbove = std::max(maxAbove, -below);
		if (below <= AGREEMENT_NATS && -below <= GRID_NATS) continue;
		const size_t nt = o.map.tables.size(), st = s.map.tables.size();
		missedTable += st < nt, extraTable += st > nt, sameTables += st == nt;
		std::printf("  %-26s %zu shapelets: oracle %8.2f (%zu tables), sampler %8.2f (%zu tables): %+.2f\n",
					problems[i].source.c_str(), problems[i].shapelets.size(), o.logPosterior, nt, s.logPosterior,
					st, -below);
		if (std::getenv("WHISKERMAP_AGREEMENT_DUMP")) dump(problems[i].shapelets, o.map, s.map);
	}
	const double rate = 100.0 * static_cast<double>(agree) / static_cast<double>(problems.size());
	const double ts = median(samplerTimes), to = median(oracleTimes);
	std::printf("oracle agreement: %zu/%zu = %.1f%% (sampler at most %.1f nats below the oracle)\n", agree,
				problems.size(), rate, AGREEMENT_NATS);
	std::printf("(looser, for context: within 5 nats %zu, within 10 nats %zu)\n", within5, within10);
	std::printf("disagreements: %zu with as many tables as the oracle, %zu with fewer, %zu with more\n", sameTables,
				missedTable, extraTable);
	std::printf("sampler above the oracle by more than %.1f nats: %zu (largest excess %+.2f)\n", GRID_NATS, above, maxAbove);
	std::printf("median time per step: sampler %.3f ms, oracle %.1f ms, ratio %.0fx\n", 1e3 * ts, 1e3 * to, to / ts);
	EXPECT_EQ(above, 0u);
	// Regression floor: the measured rate minus a margin. The target is 95% (doc/benchmarks.md
	// reports where the sampler stands against it); raise this floor as the sampler improves.
	if (params.acceptance == inference::AcceptanceRule::Gibbs)
	{
		EXPECT_GE(rate, MIN_AGREEMENT_PERCENT);
	}
}
