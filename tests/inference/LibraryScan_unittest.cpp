// The random scan of the library's moves on continuous poses (moves::libraryScan; doc/sampler.md,
// "Random scan of the library's moves") and the posterior chain it drives (PosteriorChain):
// chains at beta = 1 spend the model's posterior probabilities, against quadrature, and every
// move changes logJoint by its logTarget.
#include <whiskermap/inference/PosteriorChain.h>
#include <whiskermap/inference/moves/LibraryScan.h>

#include "ContinuousProblems.h"
#include "ScanChecks.h"

#include <cstdio>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

using namespace whiskermap;
using inference::moves::MoveContext;
using model::Id;
using model::NONE;
using test::Moments;
using test::OneContact;
using test::ThreeLegs;
using test::TwoLegs;

namespace
{
/** The library scan with every move but `keep` given weight 0 (never drawn). */
inference::RandomScan scanOf(const model::ModelParams& P, std::initializer_list<const char*> keep)
{
	inference::RandomScan scan = inference::moves::libraryScan(P);
	for (inference::ScanMove& m : scan.moves())
	{
		bool kept = false;
		for (const char* k : keep) kept = kept || m.name == k;
		if (!kept) m.weight = 0;
	}
	test::checkTargets(scan);
	return scan;
}
}  // namespace

// A leg's existence under the scan's leg birth, death and refit (broad proposals: births on the
// disc of radius w about the contact, refits a random walk that can leave it). The refit lets
// the leg stand anywhere, so the chain must spend the leg's probability over every pose (the
// integral over a disc of radius 3 w, beyond which exp(logOddsLeg) is negligible), not the
// births' disc's.
TEST(LibraryScan, SamplesALegsExistence)
{
	const OneContact one;
	const model::ModelParams& P = one.P;
	const auto& shapelets = one.shapelets;
	const inference::SamplerParams& broad = one.broad;
	const inference::Acceptance& acceptance = one.acceptance;
	const double exact = test::legProbability(P, shapelets, 3 * P.leg_width), onDisc = test::legProbability(P, shapelets, P.leg_width);

	test::ContextOnBoard run(P);
	run.bb.reset(shapelets);
	MoveContext ctx(run.bb, run.P, broad, run.rng, acceptance);
	ctx.result = &run.result;
	inference::RandomScan scan = scanOf(P, {"leg birth", "leg death", "leg refit"});
	constexpr int N = 1000000;
	int withLeg = 0;
	for (int i = 0; i < N; i++)
	{
		scan.step(ctx);
		withLeg += run.bb.shapeletParent(0) != NONE;
	}
	const double chain = static_cast<double>(withLeg) / N;
	std::printf("leg of one contact, library scan: P(leg) chain %.4f, exact %.4f (births' disc only: %.4f)\n", chain,
				exact, onDisc);
	for (size_t m = 0; m < scan.moves().size(); m++)
		if (scan.moves()[m].weight > 0)
			std::printf("  %s: %ld proposed, %ld accepted\n", scan.moves()[m].name.c_str(), scan.proposed()[m], scan.accepted()[m]);
	EXPECT_NEAR(chain, exact, 0.02);
}

// A table's existence over three fixed legs under the scan's table birth, death and refit
// (data-driven, stochastic refits). The scan draws the birth's leg among all three, and only
// the birth from the canonical leg has a reverse, so the choice probability (1/3) must be in
// the birth's density; left out, the chain keeps the table too rarely. (c_T is set so that the
// table's probability is 0.2: births are then accepted with probability about 3/4, so the
// missing 1/3 shows; at 1/2 they are accepted either way and the chain would not tell.)
TEST(LibraryScan, SamplesATablesExistence)
{
	model::ModelParams P;
	Moments m;
	P.c_T *= 0.25 * std::exp(-test::logTableOdds(P, m));  // odds 1/4
	const double exact = 1 / (1 + std::exp(-test::logTableOdds(P, m)));
	ASSERT_NEAR(exact, 0.2, 0.02);
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	rj.leg_position_noise = std::sqrt(std::max(m.var[0], m.var[1]));
	rj.leg_angle_noise = std::sqrt(m.var[2]);
	const inference::Acceptance acceptance(rj.acceptance);
	for (const bool withoutChoice : {false, true})  // withoutChoice: the birth's 1/3 left out of its density
	{
		ThreeLegs run(P);
		MoveContext ctx(run.bb, run.P, rj, run.rng, acceptance);
		ctx.result = &run.result;
		inference::RandomScan scan = scanOf(run.P, {"table birth", "table death", "table refit"});
		if (withoutChoice)
			for (inference::ScanMove& move : scan.moves())
				if (move.name == "table birth")
					move.propose = [inner = move.propose](MoveContext& c) {
						auto p = inner(c);
						if (p) p->logForward += std::log(3.0);
						return p;
					};
		constexpr int N = 150000;
		int withTable = 0;
		for (int i = 0; i < N; i++)
		{
			scan.step(ctx);
			withTable += run.bb.leg(run.legs[0]).parent != NONE;
		}
		const double chain = static_cast<double>(withTable) / N;
		std::printf("table over three legs, library scan%s: P(table) chain %.4f, exact %.4f\n",
					withoutChoice ? ", the leg's choice left out" : "", chain, exact);
		if (withoutChoice)
			EXPECT_LT(chain, exact - 0.07);
		else
			EXPECT_NEAR(chain, exact, 0.03);
	}
}

namespace
{
/** Six contacts on the faces of one corner's leg of a table, held by two free legs at the
 *  corner (three each), so that links, splits and merges between them are all proposable. */
struct TwoLegsOneCorner : test::ContextOnBoard
{
	TwoLegsOneCorner(uint64_t seed, const model::ModelParams& params) : test::ContextOnBoard(params)
	{
		rng.seed(seed);
		const model::Table& t = ThreeLegs::TRUTH;
		bb.reset(test::touchTable(t, P, {{0, 0, 0.01}, {0, 1, -0.005}, {0, 0, -0.01}, {0, 1, 0.012}, {0, 0, 0.0}, {0, 1, 0.0}}));
		for (int i = 0; i < 2; i++)
		{
			model::Leg leg;
			model::tableCorner(t, 0, P, leg.x, leg.y);
			leg.theta = t.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture;
			const Id l = bb.addLeg(leg);
			for (size_t s = static_cast<size_t>(i); s < 6; s += 2) bb.setShapeletParent(s, l);
			double ignored = 0;
			ctx.refitInPlace(l, ignored);
		}
	}
};
}  // namespace

// Every move of the scan, 3,000 steps on each of 40 random boards of the move tests and of 20
// boards of two legs sharing a corner's contacts: each accepted move changes logJoint by its
// logTarget, each rejected one leaves the board's logJoint as it was, and every move is
// accepted somewhere (the chain moves: births, deaths, links, merges and switches of legs and
// tables at beta = 1). The model is flattened as in GridProblem.h, so that the posterior
// spreads over many structures (at the defaults a table's death is all but never accepted).
// The split is proposed but not accepted here: its new leg's draw density (about e^11 per m^2
// rad) meets the flattened model's 1 m cells, a ratio of about e^-11 (its reverses are
// tested in StochasticRefits_unittest).
TEST(LibraryScan, MovesAreExactChangesOfTheJoint)
{
	model::ModelParams P;
	P.delta = 0.5, P.epsilon = 0.5, P.c_T = 1, P.c_S = 1e6, P.c_L = 1, P.alpha_L = 10;
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	const inference::Acceptance acceptance(rj.acceptance);
	inference::RandomScan total = inference::moves::libraryScan(P);
	std::vector<long> proposed(total.moves().size(), 0), accepted(total.moves().size(), 0);
	for (uint64_t seed = 1; seed <= 60; seed++)
	{
		std::unique_ptr<test::ContextOnBoard> board;
		if (seed <= 40)
			board = std::make_unique<test::MoveBoard>(seed, seed % 2 == 0, P);
		else
			board = std::make_unique<TwoLegsOneCorner>(seed, P);
		MoveContext ctx(board->bb, board->P, rj, board->rng, acceptance);
		ctx.result = &board->result;
		inference::RandomScan scan = inference::moves::libraryScan(P);
		test::checkTargets(scan);
		for (int i = 0; i < 3000; i++) scan.step(ctx);
		for (size_t m = 0; m < proposed.size(); m++) proposed[m] += scan.proposed()[m], accepted[m] += scan.accepted()[m];
	}
	for (size_t m = 0; m < proposed.size(); m++)
	{
		std::printf("  %s: %ld proposed, %ld accepted\n", total.moves()[m].name.c_str(), proposed[m], accepted[m]);
		if (total.moves()[m].name != "split")
		{
			EXPECT_GT(accepted[m], 0) << total.moves()[m].name;
		}
	}
}

// The posterior chain (inference::PosteriorChain) from the MAP board with the table over the
// three legs: the fraction of samples holding the table is its probability (0.2 by
// quadrature), and its pose spread over them is the quadrature's posterior standard deviation.
// Only the table's moves run (the quadrature holds the legs fixed).
TEST(PosteriorChain, GivesATablesExistenceAndSpread)
{
	model::ModelParams P;
	Moments m;
	P.c_T *= 0.25 * std::exp(-test::logTableOdds(P, m));
	const double exact = 1 / (1 + std::exp(-test::logTableOdds(P, m)));
	inference::SamplerParams params;
	params.leg_position_noise = std::sqrt(std::max(m.var[0], m.var[1]));
	params.leg_angle_noise = std::sqrt(m.var[2]);
	ThreeLegs map(P);
	const Id t = map.bb.addTable(ThreeLegs::TRUTH);
	for (const Id l : map.legs) map.bb.setLegParent(l, t);
	inference::PosteriorChain chain(map.P, params);
	for (inference::ScanMove& move : chain.scan().moves())
		if (move.name != "table birth" && move.name != "table death" && move.name != "table refit") move.weight = 0;
	const auto summary = chain.run(map.bb, 7, 1000, 30000, 10);
	ASSERT_EQ(summary.size(), static_cast<size_t>(t) + 1);
	const inference::PosteriorChain::Summary& s = summary[static_cast<size_t>(t)];
	std::printf("posterior chain: existence %.4f (exact %.4f); sd x %.5f (%.5f), y %.5f (%.5f), yaw %.5f (%.5f)\n",
				s.existence, exact, s.sd_x, std::sqrt(m.var[0]), s.sd_y, std::sqrt(m.var[1]), s.sd_yaw, std::sqrt(m.var[2]));
	EXPECT_NEAR(s.existence, exact, 0.03);
	EXPECT_NEAR(s.sd_x / std::sqrt(m.var[0]), 1, 0.1);
	EXPECT_NEAR(s.sd_y / std::sqrt(m.var[1]), 1, 0.1);
	EXPECT_NEAR(s.sd_yaw / std::sqrt(m.var[2]), 1, 0.1);
}

// A table and its mirror image over two legs: the scan's table moves (births and deaths,
// plain and completed, corner births and deaths of invented legs, refits and the table switch)
// must spend the model's posterior probabilities on the table, its mirror and no table,
// against quadrature of each table's pose summed over its invented legs.
TEST(LibraryScan, SamplesATableAndItsMirror)
{
	model::ModelParams P;
	Moments m, mm;
	P.c_T *= std::exp(-test::logTwoLegOdds(P, ThreeLegs::TRUTH, m));  // odds 1 for the table
	const double oddsT = std::exp(test::logTwoLegOdds(P, ThreeLegs::TRUTH, m)),
				 oddsM = std::exp(test::logTwoLegOdds(P, TwoLegs::mirror(P), mm)), z = 1 + oddsT + oddsM;
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	rj.leg_position_noise = std::sqrt(std::max(m.var[0], m.var[1]));
	rj.leg_angle_noise = std::sqrt(m.var[2]);
	const inference::Acceptance acceptance(rj.acceptance);
	TwoLegs run(P);
	MoveContext ctx(run.bb, run.P, rj, run.rng, acceptance);
	ctx.result = &run.result;
	inference::RandomScan scan = scanOf(run.P, {"table birth", "table death", "table refit", "leg birth", "leg death",
												 "table birth, completed", "table death, with its invented legs",
												 "table switch"});
	const model::Table T = ThreeLegs::TRUTH, M = TwoLegs::mirror(P);
	constexpr int N = 400000;
	long atT = 0, atM = 0;
	for (int i = 0; i < N; i++)
	{
		scan.step(ctx);
		const Id t = run.bb.leg(run.legs[0]).parent;
		if (t == NONE) continue;
		const model::Table& now = run.bb.table(t);
		atT += std::hypot(now.x - T.x, now.y - T.y) < 0.05;
		atM += std::hypot(now.x - M.x, now.y - M.y) < 0.05;
	}
	const double pT = static_cast<double>(atT) / N, pM = static_cast<double>(atM) / N;
	std::printf("table and mirror over two legs: chain %.4f / %.4f / none %.4f, exact %.4f / %.4f / %.4f\n", pT, pM,
				1 - pT - pM, oddsT / z, oddsM / z, 1 / z);
	for (size_t k = 0; k < scan.moves().size(); k++)
		if (scan.moves()[k].weight > 0)
			std::printf("  %s: %ld proposed, %ld accepted\n", scan.moves()[k].name.c_str(), scan.proposed()[k], scan.accepted()[k]);
	EXPECT_NEAR(pT, oddsT / z, 0.03);
	EXPECT_NEAR(pM, oddsM / z, 0.03);
}

