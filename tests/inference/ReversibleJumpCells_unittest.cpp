// Births and deaths under the reversible-jump acceptance on continuous poses (doc/sampler.md,
// "Cells, not densities"): chains of a leg's and of a table's birth and death at beta = 1 spend
// the model's posterior probability of the hypothesis with it, against quadrature; judged with
// a bare density, or with the table's death declaring no reverse, they do not.
#include <whiskermap/inference/PosteriorChain.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/LibraryScan.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>

#include "MoveBoards.h"
#include "PoseQuadrature.h"
#include "ScanChecks.h"

#include <cstdio>
#include <initializer_list>
#include <memory>
#include <vector>
#include <string>
#include <limits>

using namespace whiskermap;
using inference::moves::MoveContext;
using inference::moves::Proposal;
using model::Id;
using model::NONE;
using test::Moments;
using test::Pose;

namespace
{
/** One contact on a leg's face, under a model in which its leg is about as probable as none
 *  (alpha_S = 300; the defaults give 1 - 1e-4), with broad proposals judged by the
 *  reversible-jump rule. */
struct OneContact
{
	OneContact()
	{
		P.alpha_S = 300;
		shapelets = test::touchTable({0.3, -0.2, 0.4, P.leg_width, P.texture}, P, {{0, 0, 0.004}});
		broad.acceptance = inference::AcceptanceRule::ReversibleJump;
		broad.proposals = inference::Proposals::Broad;
	}
	model::ModelParams P;
	std::vector<obs::Shapelet> shapelets;
	inference::SamplerParams broad;
	inference::Acceptance acceptance{inference::AcceptanceRule::ReversibleJump};
};

/** The model's probability that shapelet 0 of `shapelets` has a free leg of its own (against
 *  none), its centre within `radius` of the contact, its yaw any: odds = the integral of
 *  exp(logOddsLeg) per (2 delta)^3 cell (logJoint counts each hypothesis as a cell's mass,
 *  eq. 19), by quadrature on a polar grid. */
double legProbability(const model::ModelParams& P, const std::vector<obs::Shapelet>& shapelets, double radius)
{
	test::ContextOnBoard q(P);
	q.bb.reset(shapelets);
	const obs::Shapelet& s = shapelets[0];
	model::Leg leg;
	leg.wx = leg.wy = P.leg_width, leg.texture = s.texture;
	const Id l = q.bb.addLeg(leg);
	q.bb.setShapeletParent(0, l);
	const int NR = 60, NPHI = 120, NYAW = 180;
	const double cell = std::pow(2 * P.delta, 3);
	double odds = 0;
	for (int i = 0; i < NR; i++)
		for (int j = 0; j < NPHI; j++)
			for (int k = 0; k < NYAW; k++)
			{
				const double r = radius * (i + 0.5) / NR, phi = 2 * M_PI * (j + 0.5) / NPHI;
				leg.x = s.x + r * std::cos(phi), leg.y = s.y + r * std::sin(phi), leg.theta = 2 * M_PI * (k + 0.5) / NYAW;
				q.bb.setLeg(l, leg);
				odds += std::exp(model::logOddsLeg(q.bb, l)) * r * (radius / NR) * (2 * M_PI / NPHI) * (2 * M_PI / NYAW) / cell;
			}
	return odds / (1 + odds);
}
}  // namespace

// Births and deaths on continuous poses: does one contact have a leg? The chain alternates a
// leg's birth for the contact (the broad proposal: centre uniform on the disc of radius w about
// it, yaw uniform; bounded, so the exact answer is a finite integral) and its death, judged by
// the reversible-jump rule at beta = 1. The model's posterior odds of the leg are the integral
// of exp(logOddsLeg) over the proposal's support per (2 delta)^3 cell (logJoint counts each
// hypothesis as a cell's mass, eq. 19), by quadrature on a polar grid. The birth's density must
// be taken per cell too (LegBirthDeath::logBirthMass); judged with the bare density the chain
// charges the leg (2 delta)^3 once more (-11.7 nats at the defaults) and all but never keeps it.
TEST(ReversibleJumpCells, LegBirthAndDeathSampleTheLegsExistence)
{
	const OneContact one;
	const model::ModelParams& P = one.P;
	const auto& shapelets = one.shapelets;
	const inference::SamplerParams& broad = one.broad;
	const inference::Acceptance& acceptance = one.acceptance;

	const double exact = legProbability(P, shapelets, P.leg_width);
	ASSERT_GT(exact, 0.2);
	ASSERT_LT(exact, 0.8);

	for (const bool bare : {false, true})  // bare: the birth judged with its density, not its cell's mass
	{
		test::ContextOnBoard run(P);
		run.bb.reset(shapelets);
		MoveContext ctx(run.bb, run.P, broad, run.rng, acceptance);
		ctx.result = &run.result;
		const double perCell = 3 * std::log(2 * P.delta);
		inference::moves::LegBirthDeath move;
		constexpr int N = 200000;
		int withLeg = 0;
		for (int i = 0; i < N; i++)
		{
			const Id own = run.bb.shapeletParent(0);
			Proposal p = own == NONE ? move.birthFor(ctx, 0) : *move.death(ctx, own);
			if (bare) (own == NONE ? p.logForward : p.logReverse) -= perCell;
			ctx.judge(move, p);
			withLeg += run.bb.shapeletParent(0) != NONE;
		}
		const double chain = static_cast<double>(withLeg) / N;
		std::printf("leg of one contact, broad births%s: P(leg) chain %.4f, exact %.4f\n",
					bare ? " judged by their bare density" : "", chain, exact);
		if (bare)
			EXPECT_LT(chain, 0.01);
		else
			EXPECT_NEAR(chain, exact, 0.02);
	}
}

namespace
{
/** Three legs of a table, each refitted to two contacts on its outer faces, free; the table's
 *  birth from its canonical leg adopts all three. */
struct ThreeLegs : test::ContextOnBoard
{
	explicit ThreeLegs(const model::ModelParams& params) : test::ContextOnBoard(params)
	{
		bb.reset(test::touchTable(
			TRUTH, P, {{0, 0, 0.01}, {0, 1, -0.005}, {1, 1, 0.0}, {1, 2, 0.01}, {3, 0, -0.01}, {3, 3, 0.005}}));
		const int corners[3] = {0, 1, 3};
		for (int i = 0; i < 3; i++)
		{
			model::Leg leg;
			model::tableCorner(TRUTH, corners[i], P, leg.x, leg.y);
			leg.theta = TRUTH.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture;
			legs[i] = bb.addLeg(leg);
			bb.setShapeletParent(static_cast<size_t>(2 * i), legs[i]);
			bb.setShapeletParent(static_cast<size_t>(2 * i + 1), legs[i]);
			double ignored = 0;
			ctx.refitInPlace(legs[i], ignored);
		}
	}
	static constexpr model::Table TRUTH{0.2, 0.1, 0.3, 0.05, 0.7};
	Id legs[3] = {NONE, NONE, NONE};
};

/** log of the model's odds of a table over the three legs against none: the integral of
 *  exp(logJoint with the table at pose x, the legs its children) over x, per eq. 19 cell
 *  (the table and its pose's posterior moments in `moments`). */
double logTableOdds(const model::ModelParams& P, Moments& moments)
{
	ThreeLegs b(P);
	const double without = model::logJoint(b.bb);
	const Id t = b.bb.addTable(ThreeLegs::TRUTH);
	for (const Id l : b.legs) b.bb.setLegParent(l, t);
	const auto logp = [&](const Pose& p) {
		return test::logJointAt(b.bb, b.bb.table(t), p, [&](const model::Table& to) { b.bb.setTable(t, to); }) - without;
	};
	moments = test::quadrature(logp, test::poseOf(ThreeLegs::TRUTH));
	return moments.logIntegral - 3 * std::log(2 * P.delta);
}
}  // namespace

// Births and deaths of a table over three fixed legs: the chain alternates the table's
// stochastic birth from its canonical leg and its death, judged by the reversible-jump rule
// at beta = 1, and its time with a table must match the model's posterior probability of the
// table (quadrature of its pose, per cell; c_T set so that it is near 1/2). Before this test
// the death declared no reverse: a born table never died (checked too).
TEST(ReversibleJumpCells, TableBirthAndDeathSampleTheTablesExistence)
{
	model::ModelParams P;
	Moments m;
	P.c_T *= std::exp(-logTableOdds(P, m));  // odds 1 at this c_T (logJoint holds log c_T once per table)
	const double exact = 1 / (1 + std::exp(-logTableOdds(P, m)));
	ASSERT_NEAR(exact, 0.5, 0.05);
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	rj.leg_position_noise = std::sqrt(std::max(m.var[0], m.var[1]));  // the pose posterior's own scale
	rj.leg_angle_noise = std::sqrt(m.var[2]);
	const inference::Acceptance acceptance(rj.acceptance);
	for (const bool noReverse : {false, true})  // noReverse: the death as it was
	{
		ThreeLegs run(P);
		MoveContext ctx(run.bb, run.P, rj, run.rng, acceptance);
		ctx.result = &run.result;
		inference::moves::TableBirthDeath move(run.P);
		constexpr int N = 40000;
		int withTable = 0;
		for (int i = 0; i < N; i++)
		{
			const Id parent = run.bb.leg(run.legs[0]).parent;
			Proposal p = parent == NONE ? move.birth(ctx, run.legs[0]) : move.death(ctx, parent);
			if (noReverse && parent != NONE) p.logReverse = -std::numeric_limits<double>::infinity();
			ctx.judge(move, p);
			withTable += run.bb.leg(run.legs[0]).parent != NONE;
		}
		const double chain = static_cast<double>(withTable) / N;
		std::printf("table over three legs%s: P(table) chain %.4f, exact %.4f\n", noReverse ? ", death without reverse" : "",
					chain, exact);
		if (noReverse)
			EXPECT_GT(chain, 0.99);
		else
			EXPECT_NEAR(chain, exact, 0.03);
	}
}

// The random scan of the library's moves (moves::libraryScan; doc/sampler.md, "Random scan of
// the library's moves"): each move draws its target and adds that draw's probability both ways.

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
TEST(ReversibleJumpCells, LibraryScanSamplesALegsExistence)
{
	const OneContact one;
	const model::ModelParams& P = one.P;
	const auto& shapelets = one.shapelets;
	const inference::SamplerParams& broad = one.broad;
	const inference::Acceptance& acceptance = one.acceptance;
	const double exact = legProbability(P, shapelets, 3 * P.leg_width), onDisc = legProbability(P, shapelets, P.leg_width);

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
TEST(ReversibleJumpCells, LibraryScanSamplesATablesExistence)
{
	model::ModelParams P;
	Moments m;
	P.c_T *= 0.25 * std::exp(-logTableOdds(P, m));  // odds 1/4
	const double exact = 1 / (1 + std::exp(-logTableOdds(P, m)));
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
TEST(ReversibleJumpCells, LibraryScanMovesAreExactChangesOfTheJoint)
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
TEST(ReversibleJumpCells, PosteriorChainGivesATablesExistenceAndSpread)
{
	model::ModelParams P;
	Moments m;
	P.c_T *= 0.25 * std::exp(-logTableOdds(P, m));
	const double exact = 1 / (1 + std::exp(-logTableOdds(P, m)));
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

namespace
{
/** Two legs on one long side of a table (corners 0 and 1), each refitted to two contacts on
 *  its outer faces, free: the table and its mirror image across them explain them equally. */
struct TwoLegs : test::ContextOnBoard
{
	explicit TwoLegs(const model::ModelParams& params) : test::ContextOnBoard(params)
	{
		bb.reset(test::touchTable(ThreeLegs::TRUTH, P, {{0, 0, 0.01}, {0, 1, -0.005}, {1, 1, 0.0}, {1, 2, 0.01}}));
		for (int i = 0; i < 2; i++)
		{
			model::Leg leg;
			model::tableCorner(ThreeLegs::TRUTH, i, P, leg.x, leg.y);
			leg.theta = ThreeLegs::TRUTH.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture;
			legs[i] = bb.addLeg(leg);
			bb.setShapeletParent(static_cast<size_t>(2 * i), legs[i]);
			bb.setShapeletParent(static_cast<size_t>(2 * i + 1), legs[i]);
			double ignored = 0;
			ctx.refitInPlace(legs[i], ignored);
		}
	}
	/** The table's mirror image across its side through corners 0 and 1. */
	static model::Table mirror(const model::ModelParams& P)
	{
		model::Table m = ThreeLegs::TRUTH;
		double x0 = 0, y0 = 0, x3 = 0, y3 = 0;  // corner 0 and the corner across the width from it
		model::tableCorner(m, 0, P, x0, y0);
		model::tableCorner(m, 3, P, x3, y3);
		m.x += x0 - x3, m.y += y0 - y3;
		return m;
	}
	Id legs[2] = {NONE, NONE};
};

/** log of the model's odds of `table` over the two legs (with or without an invented leg at
 *  each of its empty corners, exactly there) against no table, per eq. 19 cell of its pose. */
double logTwoLegOdds(const model::ModelParams& P, const model::Table& table, Moments& moments)
{
	const double without = model::logJoint(TwoLegs(P).bb);
	std::vector<std::unique_ptr<TwoLegs>> boards;  // one per set of invented legs
	std::vector<Id> tables;
	for (int mask = 0; mask < 4; mask++)
	{
		auto b = std::make_unique<TwoLegs>(P);
		const Id t = b->bb.addTable(table);
		for (const Id l : b->legs) b->bb.setLegParent(l, t);
		const model::CornerCounts counts = b->bb.cornerCounts(t);
		int k = 0;
		for (int c = 0; c < 4; c++)
			if (counts[static_cast<size_t>(c)] == 0 && (mask >> k++ & 1))
			{
				model::Leg leg;
				leg.wx = leg.wy = table.leg_width, leg.texture = table.texture;
				model::tableCorner(table, c, P, leg.x, leg.y);
				leg.theta = table.theta, leg.parent = t;
				b->bb.addLeg(leg);
			}
		EXPECT_EQ(k, 2);  // both legs at corners of the table, two corners empty
		boards.push_back(std::move(b)), tables.push_back(t);
	}
	const auto logp = [&](const Pose& p) {
		double sum = -std::numeric_limits<double>::infinity();
		for (size_t i = 0; i < boards.size(); i++)
		{
			model::Blackboard& bb = boards[i]->bb;
			model::Table moved = table;
			moved.x = p[0], moved.y = p[1], moved.theta = p[2];
			bb.setTable(tables[i], moved);
			for (const Id l : bb.legsOf(tables[i]))
				if (!bb.explains(l))
				{
					model::Leg leg = bb.leg(l);
					model::tableCorner(moved, leg.corner, P, leg.x, leg.y);
					leg.theta = moved.theta;
					bb.setLeg(l, leg);
				}
			sum = model::logSumExp(sum, model::logJoint(bb) - without);
		}
		return sum;
	};
	moments = test::quadrature(logp, test::poseOf(table), 41);
	return moments.logIntegral - 3 * std::log(2 * P.delta);
}
}  // namespace

// A table and its mirror image over two legs: the scan's table moves (births and deaths,
// plain and completed, corner births and deaths of invented legs, refits and the table switch)
// must spend the model's posterior probabilities on the table, its mirror and no table,
// against quadrature of each table's pose summed over its invented legs.
TEST(ReversibleJumpCells, LibraryScanSamplesATableAndItsMirror)
{
	model::ModelParams P;
	Moments m, mm;
	P.c_T *= std::exp(-logTwoLegOdds(P, ThreeLegs::TRUTH, m));  // odds 1 for the table
	const double oddsT = std::exp(logTwoLegOdds(P, ThreeLegs::TRUTH, m)),
				 oddsM = std::exp(logTwoLegOdds(P, TwoLegs::mirror(P), mm)), z = 1 + oddsT + oddsM;
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
