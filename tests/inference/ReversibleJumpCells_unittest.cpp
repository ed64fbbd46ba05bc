// Births and deaths under the reversible-jump acceptance on continuous poses (doc/sampler.md,
// "Cells, not densities"): chains of a leg's and of a table's birth and death at beta = 1 spend
// the model's posterior probability of the hypothesis with it, against quadrature; judged with
// a bare density, or with the table's death declaring no reverse, they do not.
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>

#include "ContinuousProblems.h"

#include <cstdio>
#include <limits>

using namespace whiskermap;
using inference::moves::MoveContext;
using inference::moves::Proposal;
using model::Id;
using model::NONE;
using test::Moments;
using test::OneContact;
using test::ThreeLegs;

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

	const double exact = test::legProbability(P, shapelets, P.leg_width);
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

// Births and deaths of a table over three fixed legs: the chain alternates the table's
// stochastic birth from its canonical leg and its death, judged by the reversible-jump rule
// at beta = 1, and its time with a table must match the model's posterior probability of the
// table (quadrature of its pose, per cell; c_T set so that it is near 1/2). Before this test
// the death declared no reverse: a born table never died (checked too).
TEST(ReversibleJumpCells, TableBirthAndDeathSampleTheTablesExistence)
{
	model::ModelParams P;
	Moments m;
	P.c_T *= std::exp(-test::logTableOdds(P, m));  // odds 1 at this c_T (logJoint holds log c_T once per table)
	const double exact = 1 / (1 + std::exp(-test::logTableOdds(P, m)));
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
