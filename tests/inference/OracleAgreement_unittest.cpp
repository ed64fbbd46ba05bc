// Does the sampler find the MAP? Its log posterior against the exact oracle's on a few
// hundred single time steps: working memories replayed from the shipped paper-arena rawlogs,
// and random contacts on random tables (doc/oracle.md). And how many proposals it needs to
// get there with its data-driven proposals and with the broad baseline (doc/sampler.md,
// "Broad proposals").
#include <gtest/gtest.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/ExactMapOracle.h>
#include <whiskermap/inference/ShapeletMemory.h>
#include <whiskermap/model/Posterior.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
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

/** Proposals a step spent: the judged proposals, plus each pose the polish's searches scored. */
uint64_t spent(const inference::StepResult& r)
{
	uint64_t n = r.poseEvaluations;
	for (const uint32_t k : r.proposed) n += k;
	return n;
}

/** Proposals the sampler needs to first hold a board at least `target` (logJoint): steps
 *  from seed, seed + 1, ... (restarts), each counted whole until the one that gets there,
 *  counted up to that change. nullopt if `budget` proposals do not get there. */
std::optional<uint64_t> proposalsToReach(
	BlackboardSampler& sampler, const std::vector<obs::Shapelet>& shapelets, double target, uint64_t seed,
	uint64_t budget)
{
	uint64_t before = 0;
	std::optional<uint64_t> reached;
	sampler.watch([&](const model::Blackboard& bb, const inference::StepResult& r) {
		if (!reached && model::logJoint(bb) >= target) reached = before + spent(r);
	});
	for (uint64_t run = 0; !reached && before < budget; run++) before += spent(sampler.step(shapelets, seed + run));
	sampler.watch({});
	if (reached && *reached <= budget) return reached;
	return std::nullopt;
}

/** The problems, the sampler's step and the oracle's answer on each: computed once for the
 *  tests below (the oracle takes most of the time). */
class OracleAgreement : public ::testing::Test
{
   protected:
	struct Outcome
	{
		inference::StepResult sampler;
		inference::OracleResult oracle;
		double samplerSeconds, oracleSeconds;
	};
	static std::vector<Problem> problems;
	static std::vector<Outcome> out;
	static SamplerParams params;

	static void SetUpTestSuite()
	{
		fromRawlog("default.rawlog", 5, problems);
		fromRawlog("noiseless.rawlog", 5, problems);
		synthetic(100, problems);
		// WHISKERMAP_AGREEMENT_ACCEPTANCE=reversible_jump measures the other acceptance rule
		// (doc/sampler.md); the regression floor holds for the default rule only.
		const char* rule = std::getenv("WHISKERMAP_AGREEMENT_ACCEPTANCE");
		if (rule && std::string(rule) == "reversible_jump") params.acceptance = inference::AcceptanceRule::ReversibleJump;
		if (rule && std::string(rule) != "gibbs" && std::string(rule) != "reversible_jump") return;
		// Two workers (the oracle is const; one sampler each); seeds depend only on the problem.
		out.resize(problems.size());
		const ExactMapOracle oracle(P);
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
	}
};
std::vector<Problem> OracleAgreement::problems;
std::vector<OracleAgreement::Outcome> OracleAgreement::out;
SamplerParams OracleAgreement::params;
}  // namespace

/** Measured 98.5% (256/260) with the polish's sliding table and contact exchange (95.4%
 *  before them, 88.1% before the shared leg pose search, 13.5% before any pose move); floor
 *  with a margin. */
constexpr double MIN_AGREEMENT_PERCENT = 95.0;

TEST_F(OracleAgreement, SamplerFindsTheExactMap)
{
	ASSERT_GE(problems.size(), 200u);
	ASSERT_EQ(out.size(), problems.size()) << "WHISKERMAP_AGREEMENT_ACCEPTANCE must be gibbs or reversible_jump";

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

/** The broad baseline runs its schedule this many times longer (sweeps per temperature and
 *  coldest sweeps): the best of the factors 1, 3, 10, 15, 20, 30, 50, 100, 300 and 1000 for it
 *  (its median proposals to the optimum were 2,326 at 20, 2,656 at 30, 3,494 at 15, 6,663 at
 *  10 and over 10^5 at 1; doc/sampler.md, "Broad proposals"). */
constexpr int BROAD_SCHEDULE_FACTOR = 20;

/** Proposals (judged moves plus the poses the polish's searches scored) until the sampler
 *  first holds a board within AGREEMENT_NATS of the oracle's optimum, restarting with a new
 *  seed after each step that does not get there, up to a budget (env
 *  WHISKERMAP_PROPOSAL_BUDGET, default 10^6): the data-driven proposals against the broad
 *  baseline (doc/sampler.md, "Broad proposals"), median over the oracle set. Issue 10 asks
 *  the data-driven ones to need at least 10 times fewer. */
TEST_F(OracleAgreement, DataDrivenProposalsNeedFewerThanBroadOnes)
{
	ASSERT_EQ(out.size(), problems.size());
	const char* env = std::getenv("WHISKERMAP_PROPOSAL_BUDGET");
	const uint64_t budget = env ? std::stoull(env) : 1000000;
	SamplerParams broad = params;
	broad.proposals = inference::Proposals::Broad;
	broad.sweeps_per_temperature *= BROAD_SCHEDULE_FACTOR;
	broad.coldest_sweeps *= BROAD_SCHEDULE_FACTOR;
	// need[0]: data-driven, need[1]: broad; budget + 1 stands for "not within the budget".
	std::vector<uint64_t> need[2] = {std::vector<uint64_t>(problems.size()), std::vector<uint64_t>(problems.size())};
	const auto work = [&](size_t first) {
		BlackboardSampler samplers[2] = {{P, params}, {P, broad}};
		for (size_t i = first; i < problems.size(); i += 2)
			for (int k = 0; k < 2; k++)
				need[k][i] = proposalsToReach(samplers[k], problems[i].shapelets,
											  out[i].oracle.logPosterior - AGREEMENT_NATS, i, budget)
								 .value_or(budget + 1);
	};
	std::thread other(work, 1);
	work(0);
	other.join();

	double medians[2];
	for (int k = 0; k < 2; k++)
	{
		std::vector<double> v(need[k].begin(), need[k].end());
		const size_t reached = static_cast<size_t>(std::count_if(need[k].begin(), need[k].end(), [&](uint64_t n) { return n <= budget; }));
		std::sort(v.begin(), v.end());
		medians[k] = v[v.size() / 2];
		const auto show = [&](double q) {
			const double x = v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
			return x > static_cast<double>(budget) ? std::string("> budget") : std::to_string(static_cast<uint64_t>(x));
		};
		std::printf("proposals to the oracle's optimum, %-11s: median %s, quartiles %s / %s, 90%% %s; reached on %zu/%zu within %llu\n",
					k ? "broad" : "data-driven", show(0.5).c_str(), show(0.25).c_str(), show(0.75).c_str(),
					show(0.9).c_str(), reached, problems.size(), static_cast<unsigned long long>(budget));
	}
	std::printf("broad / data-driven medians: %s%.1fx\n", medians[1] > static_cast<double>(budget) ? ">= " : "",
				std::min(medians[1], static_cast<double>(budget)) / medians[0]);
	EXPECT_LE(medians[0], static_cast<double>(budget));
	EXPECT_GE(medians[1], 10 * medians[0]);
}
