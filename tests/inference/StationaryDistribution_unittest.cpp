// Stationary distribution of the reversible-jump chain (issue 10; doc/sampler.md, "Random scan
// on a pose grid"): at beta = 1, on a problem small enough to enumerate (3 shapelets, legs and
// tables restricted to a few grid poses), the histogram of the states the random-scan chain
// visits (tables and their poses, legs with their grid poses and parent links, which leg each
// shapelet is on) matches the exact posterior from logJoint: a chi-squared test, p > 0.001.
// The same test run with one reverse density dropped must fail (p < 0.001): the test can fail.
// Steps: WHISKERMAP_STATIONARY_STEPS, default 10^6 (3 * 10^5 under
// the sanitizers).
#include <gtest/gtest.h>
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/moves/GridScan.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/model/Posterior.h>

#include "SyntheticTable.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

using namespace whiskermap;
using inference::moves::MoveContext;
using inference::moves::PoseGrid;
using model::Id;
using model::NONE;

namespace
{
#if defined(__SANITIZE_ADDRESS__)
constexpr long DEFAULT_STEPS = 300000;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr long DEFAULT_STEPS = 300000;
#else
constexpr long DEFAULT_STEPS = 1000000;
#endif
#else
constexpr long DEFAULT_STEPS = 1000000;
#endif

long steps()
{
	const char* env = std::getenv("WHISKERMAP_STATIONARY_STEPS");
	return env ? std::atol(env) : DEFAULT_STEPS;
}

/** The problem: 3 contacts on two legs of a known table, a grid of 3 leg poses (the two true
 *  legs and one 8 mm off) and 2 table poses (the true one and one 1 cm off). */
struct Problem
{
	model::ModelParams P;
	inference::SamplerParams S;
	std::vector<obs::Shapelet> shapelets;
	PoseGrid grid;

	Problem()
	{
		P.delta = 0.5, P.epsilon = 0.5, P.c_T = 1, P.c_S = 1e6, P.c_L = 1, P.alpha_L = 10;
		const model::Table t{0, 0, 0.3, P.leg_width, P.texture};
		shapelets = test::touchTable(t, P, {{0, 0, 0}, {0, 1, 0.01}, {1, 2, 0}});
		for (const int corner : {0, 1})
		{
			model::Leg l;
			model::tableCorner(t, corner, P, l.x, l.y);
			l.theta = t.theta, l.wx = l.wy = P.leg_width, l.texture = P.texture;
			grid.legs.push_back(l);
		}
		grid.legs.push_back(grid.legs[0]);
		grid.legs.back().x += 0.008;
		grid.tables = {t, t};
		grid.tables[1].x += 0.01;
	}
};

/** The state as a string: the table's grid index (or -), then per shapelet the rank of its
 *  leg in order of first appearance (or -), then per leg its grid index and parent flag. */
std::string stateKey(const model::Blackboard& bb, const PoseGrid& grid)
{
	std::string key = "T";
	for (Id t = 0; t < bb.tableIdBound(); t++)
		if (bb.hasTable(t)) key += std::to_string(grid.tableIndex(bb.table(t)));
	key += " S";
	std::vector<Id> order;
	for (size_t s = 0; s < bb.shapelets().size(); s++)
	{
		const Id l = bb.shapeletParent(s);
		if (l == NONE)
		{
			key += '-';
			continue;
		}
		size_t r = 0;
		while (r < order.size() && order[r] != l) r++;
		if (r == order.size()) order.push_back(l);
		key += std::to_string(r);
	}
	key += " L" + std::to_string(bb.legCount() - order.size());  // legs explaining nothing (none here)
	for (const Id l : order) key += " g" + std::to_string(grid.legIndex(bb.leg(l))) + (bb.leg(l).parent == NONE ? "f" : "p");
	return key;
}

/** Every state of the grid problem with its exact posterior probability (from logJoint). */
std::map<std::string, double> exactPosterior(const Problem& pr)
{
	std::map<std::string, double> logs;
	const size_t n = pr.shapelets.size(), g = pr.grid.legs.size();
	model::Blackboard bb(pr.P);
	inference::SamplerRandom rng;
	const inference::Acceptance acceptance;
	MoveContext ctx(bb, pr.P, pr.S, rng, acceptance);
	std::vector<int> block(n, -1);
	// Assignments of shapelets to legs (restricted growth: leg b first appears before b + 1).
	const auto visit = [&](int blocks) {
		size_t combos = 1;
		for (int b = 0; b < blocks; b++) combos *= 2 * g;
		for (int t = -1; t < static_cast<int>(pr.grid.tables.size()); t++)
			for (size_t c = 0; c < combos; c++)
			{
				bb.reset(pr.shapelets);
				const Id table = t < 0 ? NONE : bb.addTable(pr.grid.tables[static_cast<size_t>(t)]);
				bool valid = true;
				std::vector<Id> legs;
				for (size_t b = 0, code = c; b < static_cast<size_t>(blocks); b++, code /= 2 * g)
				{
					legs.push_back(bb.addLeg(pr.grid.legs[code % (2 * g) / 2]));
					if (code % 2 == 0) continue;
					valid = valid && table != NONE && inference::moves::LegReparent::withinGate(ctx, legs.back(), table);
					if (valid) bb.setLegParent(legs.back(), table);
				}
				if (!valid) continue;
				for (size_t s = 0; s < n; s++)
					if (block[s] >= 0) bb.setShapeletParent(s, legs[static_cast<size_t>(block[s])]);
				const std::string key = stateKey(bb, pr.grid);
				EXPECT_EQ(logs.count(key), 0u) << key;
				logs[key] = model::logJoint(bb);
			}
	};
	const auto assign = [&](auto& self, size_t s, int blocks) -> void {
		if (s == n) return visit(blocks);
		for (int b = -1; b <= blocks; b++)
		{
			block[s] = b;
			self(self, s + 1, std::max(blocks, b + 1));
		}
	};
	assign(assign, 0, 0);
	double top = -INFINITY, z = 0;
	for (const auto& kv : logs) top = std::max(top, kv.second);
	for (const auto& kv : logs) z += std::exp(kv.second - top);
	std::map<std::string, double> p;
	for (const auto& kv : logs) p[kv.first] = std::exp(kv.second - top) / z;
	return p;
}

/** Wraps every move of `scan` so that each accepted proposal's logTarget is checked against
 *  the change of logJoint itself (1e-7). */
void checkTargets(inference::RandomScan& scan)
{
	for (inference::ScanMove& m : scan.moves())
	{
		const auto before = std::make_shared<double>(0), target = std::make_shared<double>(0);
		m.propose = [=, inner = m.propose](MoveContext& c) {
			*before = model::logJoint(c.bb);
			auto p = inner(c);
			if (p) *target = p->logTarget;
			return p;
		};
		m.finish = [=, inner = m.finish, name = m.name](MoveContext& c, bool yes) {
			inner(c, yes);
			if (yes)
			{
				EXPECT_NEAR(model::logJoint(c.bb) - *before, *target, 1e-7) << name;
			}
		};
	}
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
	checkTargets(checked);
	runChain(pr, checked, exact, 20000, 2);  // its chi-squared is not tested: only the targets

	inference::RandomScan scan = inference::moves::gridScan(pr.grid);
	const ChiSquared right = runChain(pr, scan, exact, n, 1);
	EXPECT_EQ(right.unknown, 0);
	EXPECT_GT(right.df, 5);
	EXPECT_GT(right.p, 1e-3) << "chi2 " << right.statistic << " df " << right.df;

	// The same chain with the leg death's reverse density (the grid birth's -log N - log |G|)
	// dropped: the chain then favours deaths, and the test must see it.
	inference::RandomScan wrong = inference::moves::gridScan(pr.grid);
	auto& death = wrong.moves()[1];
	ASSERT_EQ(death.name, "grid leg death");
	death.propose = [inner = death.propose](MoveContext& c) {
		auto p = inner(c);
		if (p) p->logReverse = 0;
		return p;
	};
	const ChiSquared dropped = runChain(pr, wrong, exact, n, 1);
	EXPECT_LT(dropped.p, 1e-3) << "chi2 " << dropped.statistic << " df " << dropped.df;
}
