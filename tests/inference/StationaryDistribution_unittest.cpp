// Stationary distribution of the reversible-jump chain (issue 10; doc/sampler.md, "Random scan
// on a pose grid"): at beta = 1, on a problem small enough to enumerate (3 shapelets, legs and
// tables restricted to a few grid poses), the histogram of the states the random-scan chain
// visits (tables and their poses, legs with their grid poses and parent links, which leg each
// shapelet is on) matches the exact posterior from logJoint: a chi-squared test, p > 0.001.
// The same test run with one reverse density dropped must fail (p < 0.001): the test can fail.
// Steps: WHISKERMAP_STATIONARY_STEPS, default 10^6 (3 * 10^5 under the sanitizers).
#include <gtest/gtest.h>
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/moves/GridScan.h>
#include <whiskermap/model/Posterior.h>

#include "GridProblem.h"
#include "ScanChecks.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

using namespace whiskermap;
using inference::moves::MoveContext;
using Problem = test::GridProblem;
constexpr auto stateKey = test::gridStateKey;

namespace
{
long steps() { return test::lengthFromEnv("WHISKERMAP_STATIONARY_STEPS", 1000000, 300000); }

/** Every state of the grid problem with its exact posterior probability (from logJoint). */
std::map<std::string, double> exactPosterior(const Problem& pr)
{
	std::map<std::string, double> logs;
	test::forEachGridState(pr, pr.shapelets, [&](const model::Blackboard& bb) {
		const std::string key = stateKey(bb, pr.grid);
		EXPECT_EQ(logs.count(key), 0u) << key;
		logs[key] = model::logJoint(bb);
	});
	double top = -INFINITY, z = 0;
	for (const auto& kv : logs) top = std::max(top, kv.second);
	for (const auto& kv : logs) z += std::exp(kv.second - top);
	std::map<std::string, double> p;
	for (const auto& kv : logs) p[kv.first] = std::exp(kv.second - top) / z;
	return p;
}

struct ChiSquared
{
	double statistic = 0, p = 0;
	int df = 0;
	long unknown = 0;  ///< samples of states outside the enumeration
};

/** Upper tail of the chi-squared distribution (Wilson-Hilferty: accurate to ~1e-3 relative
 *  at these degrees of freedom). */
double chiSquaredTail(double x, int df)
{
	const double k = df, z = (std::cbrt(x / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
	return 0.5 * std::erfc(z / std::sqrt(2.0));
}

/** Runs the chain from the empty board for `n` steps (beta = 1, reversible jump), samples the
 *  state every THIN steps after a burn-in, and tests the histogram against `exact`: states
 *  expected at least 5 times are bins of their own, the rest one pooled bin. */
ChiSquared runChain(const Problem& pr, inference::RandomScan& scan, const std::map<std::string, double>& exact, long n,
					uint64_t seed)
{
	constexpr long THIN = 50, BURN_IN = 10000;  // thinned: about 50 steps between independent states
	model::Blackboard bb(pr.P);
	bb.reset(pr.shapelets);
	inference::SamplerRandom rng;
	rng.seed(seed);
	const inference::Acceptance acceptance(inference::AcceptanceRule::ReversibleJump);
	inference::StepResult result;
	MoveContext ctx(bb, pr.P, pr.S, rng, acceptance);
	ctx.result = &result;
	ctx.beta = 1;
	std::map<std::string, long> seen;
	ChiSquared out;
	long samples = 0;
	for (long i = 0; i < BURN_IN + n; i++)
	{
		scan.step(ctx);
		if (i < BURN_IN || i % THIN) continue;
		const std::string key = stateKey(bb, pr.grid);
		if (!exact.count(key)) out.unknown++;
		seen[key]++;
		samples++;
	}
	double pooledExpected = 0;
	long pooledSeen = 0;
	for (const auto& [key, p] : exact)
	{
		const double e = p * static_cast<double>(samples);
		const long o = seen.count(key) ? seen.at(key) : 0;
		if (e < 5)
		{
			pooledExpected += e, pooledSeen += o;
			continue;
		}
		out.statistic += (o - e) * (o - e) / e;
		out.df++;
	}
	if (pooledExpected > 0)
	{
		out.statistic += (pooledSeen - pooledExpected) * (pooledSeen - pooledExpected) / pooledExpected;
		out.df++;
	}
	out.df--;
	out.p = out.df > 0 ? chiSquaredTail(out.statistic, out.df) : 1;
	for (size_t m = 0; m < scan.moves().size(); m++)
		std::printf("  %-18s proposed %8ld accepted %8ld\n", scan.moves()[m].name.c_str(), scan.proposed()[m],
					scan.accepted()[m]);
	std::printf("  %ld samples (every %ld of %ld steps), chi2 = %.1f, df = %d, p = %.3g\n", samples, THIN, n,
				out.statistic, out.df, out.p);
	return out;
}
}  // namespace

TEST(StationaryDistribution, ReversibleJumpChainMatchesTheExactPosterior)
{
	const Problem pr;
	const std::map<std::string, double> exact = exactPosterior(pr);
	std::vector<std::pair<double, std::string>> top;
	for (const auto& [key, p] : exact) top.push_back({p, key});
	std::sort(top.rbegin(), top.rend());
	std::printf("%zu states; most probable:\n", exact.size());
	for (size_t i = 0; i < std::min<size_t>(8, top.size()); i++) std::printf("  %.4f %s\n", top[i].first, top[i].second.c_str());
	const long n = steps();

	inference::RandomScan checked = inference::moves::gridScan(pr.grid);
	test::checkTargets(checked);
	runChain(pr, checked, exact, 20000, 2);  // its chi-squared is not tested: only the targets

	inference::RandomScan scan = inference::moves::gridScan(pr.grid);
	const ChiSquared right = runChain(pr, scan, exact, n, 1);
	EXPECT_EQ(right.unknown, 0);
	EXPECT_GT(right.df, 5);
	EXPECT_GT(right.p, 1e-3) << "chi2 " << right.statistic << " df " << right.df;

	// The same chain with the leg death's reverse density (the grid birth's -log N - log |G|)
	// dropped: the chain then favours deaths, and the test must see it.
	inference::RandomScan wrong = test::gridScanWithoutDeathReverse(pr.grid);
	const ChiSquared dropped = runChain(pr, wrong, exact, n, 1);
	EXPECT_LT(dropped.p, 1e-3) << "chi2 " << dropped.statistic << " df " << dropped.df;
}
