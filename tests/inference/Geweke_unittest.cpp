// Geweke's joint-distribution test (Geweke 2004, JASA 99: 799-804) of the reversible-jump
// chain (issue 10; doc/sampler.md, "Random scan on a pose grid"), on the grid problem with
// discrete data: each of the 3 shapelets is one of 4 candidate contacts, so the model's joint
// P(board, shapelets) ~ exp(logJoint) is enumerable (1053 boards x 64 data sets).
// - Marginal-conditional simulator: independent draws (board, shapelets) from that joint: the
//   model's prior simulator for this problem.
// - Successive-conditional simulator: alternately shapelets ~ P(shapelets | board) (an exact
//   Gibbs sweep) and 100 steps of the chain on P(board | shapelets).
// Both have the joint as their distribution iff the chain leaves P(board | shapelets)
// invariant: the means of 5 test functions must agree (z-test, |z| < 4, the successive
// simulator's variance from batch means). The same with the leg death's reverse density
// dropped must fail (some |z| > 4). Iterations: WHISKERMAP_GEWEKE_ITERATIONS, default 10000
// (3000 under the sanitizers).
#include <gtest/gtest.h>
#include <whiskermap/inference/moves/GridScan.h>
#include <whiskermap/model/Posterior.h>

#include "GridProblem.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

using namespace whiskermap;
using inference::moves::MoveContext;
using model::Id;
using model::NONE;

namespace
{
constexpr size_t FUNCTIONS = 5, CANDIDATES = 4, STEPS_PER_ITERATION = 100, BATCHES = 20;
using Values = std::array<double, FUNCTIONS>;
const char* const NAMES[FUNCTIONS] = {"legs", "table", "explained shapelets", "legs on the table",
									  "table x shapelets = candidate 0"};

/** The candidate contacts: the problem's three and a fourth on the other face of leg 1. */
std::vector<obs::Shapelet> candidates(const test::GridProblem& pr)
{
	std::vector<obs::Shapelet> c = pr.shapelets;
	c.push_back(test::touchTable(pr.grid.tables[0], pr.P, {{1, 3, 0}})[0]);
	return c;
}

/** The test functions g(board, data); `y` holds the candidate index of each shapelet. */
Values testFunctions(const model::Blackboard& bb, const std::array<size_t, 3>& y)
{
	Values g{};
	g[0] = static_cast<double>(bb.legCount());
	g[1] = static_cast<double>(bb.tableCount());
	for (size_t s = 0; s < 3; s++) g[2] += bb.shapeletParent(s) != NONE;
	for (Id l = 0; l < bb.legIdBound(); l++) g[3] += bb.hasLeg(l) && bb.leg(l).parent != NONE;
	for (size_t s = 0; s < 3; s++) g[4] += g[1] * (y[s] == 0);
	return g;
}

std::vector<obs::Shapelet> data(const std::vector<obs::Shapelet>& c, const std::array<size_t, 3>& y)
{
	return {c[y[0]], c[y[1]], c[y[2]]};
}

struct Moments
{
	Values mean{}, variance{};  ///< of the mean (batch means for the chain)
};

/** Marginal-conditional: n independent draws from the enumerated joint. */
Moments marginalConditional(const test::GridProblem& pr, size_t n)
{
	const std::vector<obs::Shapelet> c = candidates(pr);
	std::vector<double> logs;
	std::vector<Values> values;
	for (size_t code = 0; code < CANDIDATES * CANDIDATES * CANDIDATES; code++)
	{
		const std::array<size_t, 3> y{code % CANDIDATES, code / CANDIDATES % CANDIDATES, code / (CANDIDATES * CANDIDATES)};
		test::forEachGridState(pr, data(c, y), [&](const model::Blackboard& bb) {
			logs.push_back(model::logJoint(bb));
			values.push_back(testFunctions(bb, y));
		});
	}
	const double top = *std::max_element(logs.begin(), logs.end());
	std::vector<double> cdf;
	double z = 0;
	for (const double l : logs) cdf.push_back(z += std::exp(l - top));
	Values exact{};
	for (size_t i = 0; i < values.size(); i++)
		for (size_t f = 0; f < FUNCTIONS; f++) exact[f] += std::exp(logs[i] - top) / z * values[i][f];
	std::printf("  exact means: %.4f %.4f %.4f %.4f %.4f\n", exact[0], exact[1], exact[2], exact[3], exact[4]);
	std::mt19937_64 random(7);
	Moments m;
	Values square{};
	for (size_t i = 0; i < n; i++)
	{
		const double u = std::uniform_real_distribution<double>(0, z)(random);
		const Values& g = values[static_cast<size_t>(std::upper_bound(cdf.begin(), cdf.end(), u) - cdf.begin())];
		for (size_t f = 0; f < FUNCTIONS; f++) m.mean[f] += g[f] / n, square[f] += g[f] * g[f] / n;
	}
	for (size_t f = 0; f < FUNCTIONS; f++) m.variance[f] = (square[f] - m.mean[f] * m.mean[f]) / n;
	return m;
}

/** Successive-conditional: n iterations of (data | board exactly, board | data by the chain). */
Moments successiveConditional(const test::GridProblem& pr, inference::RandomScan& scan, size_t n)
{
	const std::vector<obs::Shapelet> c = candidates(pr);
	model::Blackboard bb(pr.P), next(pr.P), probe(pr.P);
	std::array<size_t, 3> y{0, 1, 2};
	bb.reset(data(c, y));
	inference::SamplerRandom rng;
	rng.seed(3);
	const inference::Acceptance acceptance(inference::AcceptanceRule::ReversibleJump);
	inference::StepResult result;
	std::vector<Values> batches(BATCHES, Values{});
	const size_t burnIn = n / 20, perBatch = n / BATCHES;
	for (size_t i = 0; i < burnIn + perBatch * BATCHES; i++)
	{
		// Data | board: a Gibbs sweep, each shapelet drawn from its 4 candidates given the
		// board and the others (exact conditionals of logJoint).
		for (size_t s = 0; s < 3; s++)
		{
			double w[CANDIDATES], total = 0;
			for (size_t k = 0; k < CANDIDATES; k++)
			{
				std::array<size_t, 3> yk = y;
				yk[s] = k;
				test::withShapelets(bb, data(c, yk), probe);
				w[k] = model::logJoint(probe);
			}
			const double top = *std::max_element(w, w + CANDIDATES);
			for (double& v : w) total += v = std::exp(v - top);
			double u = rng.uniform() * total;
			size_t k = 0;
			while (k + 1 < CANDIDATES && u >= w[k]) u -= w[k++];
			y[s] = k;
		}
		test::withShapelets(bb, data(c, y), next);
		std::swap(bb, next);
		// Board | data: the chain.
		MoveContext ctx(bb, pr.P, pr.S, rng, acceptance);
		ctx.result = &result;
		ctx.beta = 1;
		for (size_t k = 0; k < STEPS_PER_ITERATION; k++) scan.step(ctx);
		if (i < burnIn) continue;
		const Values g = testFunctions(bb, y);
		for (size_t f = 0; f < FUNCTIONS; f++) batches[(i - burnIn) / perBatch][f] += g[f] / perBatch;
	}
	Moments m;
	for (const Values& b : batches)
		for (size_t f = 0; f < FUNCTIONS; f++) m.mean[f] += b[f] / BATCHES;
	for (const Values& b : batches)
		for (size_t f = 0; f < FUNCTIONS; f++)
			m.variance[f] += (b[f] - m.mean[f]) * (b[f] - m.mean[f]) / (BATCHES - 1) / BATCHES;
	return m;
}

/** Largest |z| over the test functions, printing each. */
double largestZ(const Moments& mc, const Moments& sc)
{
	double largest = 0;
	for (size_t f = 0; f < FUNCTIONS; f++)
	{
		const double z = (mc.mean[f] - sc.mean[f]) / std::sqrt(mc.variance[f] + sc.variance[f]);
		std::printf("  %-32s marginal-conditional %.4f  successive-conditional %.4f  z = %+.2f\n", NAMES[f], mc.mean[f],
					sc.mean[f], z);
		largest = std::max(largest, std::abs(z));
	}
	return largest;
}
}  // namespace

TEST(Geweke, SuccessiveConditionalMatchesMarginalConditional)
{
	const test::GridProblem pr;
	const auto n = static_cast<size_t>(test::lengthFromEnv("WHISKERMAP_GEWEKE_ITERATIONS", 10000, 3000));
	const Moments mc = marginalConditional(pr, n);

	inference::RandomScan scan = inference::moves::gridScan(pr.grid);
	EXPECT_LT(largestZ(mc, successiveConditional(pr, scan, n)), 4);

	// The leg death's reverse density dropped: the chain no longer leaves P(board | data)
	// invariant, and the test must see it.
	inference::RandomScan wrong = test::gridScanWithoutDeathReverse(pr.grid);
	EXPECT_GT(largestZ(mc, successiveConditional(pr, wrong, n)), 4);
}
