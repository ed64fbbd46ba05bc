// Stochastic refits under the reversible-jump acceptance (doc/sampler.md, "Stochastic
// refits"): on continuous poses, a chain of one refit move at beta = 1 samples the model's
// posterior of the pose it moves (its mean and variance against quadrature of exp(logJoint)),
// and fails to when the move's reverse density is dropped; the links, splits and merges that
// refit legs declare their reverse wherever the leg they leave stays, and score the exact
// change of logJoint.
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/inference/moves/SplitMerge.h>
#include <whiskermap/inference/moves/TableRefit.h>

#include "MoveBoards.h"
#include "PoseQuadrature.h"

#include <cstdio>
#include <functional>
#include <limits>
#include <string>

using namespace whiskermap;
using inference::moves::MoveContext;
using inference::moves::Proposal;
using model::Id;
using model::NONE;
using test::MoveBoard;
using test::Moments;
using test::Pose;
using test::logJointAt;
using test::poseOf;
using test::quadrature;

namespace
{
/** Runs `steps` proposals of `propose` at beta = 1 with the reversible-jump acceptance and
 *  returns the moments of the pose `pose()` over the chain (after 1,000 steps). With
 *  `dropReverse` every proposal is judged as if symmetric (logReverse = logForward). */
template <class M>
Moments chain(
	MoveContext& ctx, M& move, const std::function<std::optional<Proposal>()>& propose,
	const std::function<Pose()>& pose, int steps, bool dropReverse)
{
	Pose m1{}, m2{};
	int counted = 0;
	for (int i = 0; i < steps; i++)
	{
		std::optional<Proposal> p = propose();
		if (p)
		{
			if (dropReverse) p->logReverse = p->logForward;
			ctx.judge(move, *p);
		}
		if (i < 1000) continue;
		const Pose q = pose();
		for (size_t a = 0; a < 3; a++) m1[a] += q[a], m2[a] += q[a] * q[a];
		counted++;
	}
	Moments out;
	for (size_t a = 0; a < 3; a++)
		out.mean[a] = m1[a] / counted, out.var[a] = m2[a] / counted - out.mean[a] * out.mean[a];
	return out;
}

/** The chain's moments match the quadrature's: means within a tenth of a standard deviation,
 *  variances within 10%. Prints both (doc/sampler.md quotes them). */
bool matches(const Moments& chainMoments, const Moments& exact, const std::string& what)
{
	std::printf("%s: variance / exact (x, y, yaw) %.3f %.3f %.3f; mean - exact, in sd %+.3f %+.3f %+.3f\n", what.c_str(),
				chainMoments.var[0] / exact.var[0], chainMoments.var[1] / exact.var[1], chainMoments.var[2] / exact.var[2],
				(chainMoments.mean[0] - exact.mean[0]) / std::sqrt(exact.var[0]),
				(chainMoments.mean[1] - exact.mean[1]) / std::sqrt(exact.var[1]),
				(chainMoments.mean[2] - exact.mean[2]) / std::sqrt(exact.var[2]));
	for (size_t a = 0; a < 3; a++)
	{
		const double sd = std::sqrt(exact.var[a]);
		if (std::abs(chainMoments.mean[a] - exact.mean[a]) > 0.1 * sd) return false;
		if (std::abs(chainMoments.var[a] / exact.var[a] - 1) > 0.1) return false;
	}
	return true;
}

/** Reversible-jump sampler parameters whose refit noise is the posterior's own scale
 *  (position: the larger of the x and y standard deviations; yaw: its). */
inference::SamplerParams reversibleJump(const Moments& exact)
{
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	rj.leg_position_noise = std::sqrt(std::max(exact.var[0], exact.var[1]));
	rj.leg_angle_noise = std::sqrt(exact.var[2]);
	return rj;
}

constexpr int STEPS = 100000;
}  // namespace

// The table of a board with its legs held where they are: its pose's posterior given them.
// The stochastic table refit draws about the fit to the legs, and its reverse density is what
// makes the chain sample that posterior; judged as symmetric it samples a narrower one
// (exp(logJoint) times the proposal density), which the test must see.
TEST(StochasticRefits, TableRefitChainSamplesThePosteriorOfTheTablePose)
{
	for (const uint64_t seed : {3u, 8u})
	{
		MoveBoard b(seed, true);
		const Id t = b.table;
		const auto logp = [&](const Pose& p) {
			return logJointAt(b.bb, b.bb.table(t), p, [&](const model::Table& to) { b.bb.setTable(t, to); });
		};
		const Moments exact = quadrature(logp, poseOf(b.bb.table(t)));
		const inference::SamplerParams rj = reversibleJump(exact);
		const inference::Acceptance acceptance(rj.acceptance);
		for (const bool drop : {false, true})
		{
			MoveBoard run(seed, true);
			MoveContext ctx(run.bb, run.P, rj, run.rng, acceptance);
			ctx.result = &run.result;
			inference::moves::TableRefit move;
			const Moments m = chain(
				ctx, move, [&] { return move.propose(ctx, t); }, [&] { return poseOf(run.bb.table(t)); }, STEPS, drop);
			const std::string what = "table refit, board " + std::to_string(seed) + (drop ? ", reverse dropped" : "");
			EXPECT_EQ(matches(m, exact, what), !drop) << what;
			EXPECT_GT(run.result.accepted[static_cast<size_t>(inference::Move::Refit)], STEPS / 10);
		}
	}
}

// A free leg with contacts on two faces: its pose's posterior given them. Its fit pulls a
// little towards the leg's current centre, so the proposal is not an independence sampler:
// the reverse density is the old pose's about the fit from the new pose.
TEST(StochasticRefits, LegRefitChainSamplesThePosteriorOfAFreeLegPose)
{
	const model::ModelParams P;
	const model::Table t{0.3, -0.2, 0.4, P.leg_width, P.texture};
	const auto shapelets = test::touchTable(t, P, {{0, 0, -0.01}, {0, 0, 0.012}, {0, 1, 0.005}});
	const auto makeBoard = [&](test::ContextOnBoard& c) {
		c.bb.reset(shapelets);
		model::Leg leg;
		model::tableCorner(t, 0, P, leg.x, leg.y);
		leg.theta = t.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture;
		const Id l = c.bb.addLeg(leg);
		for (size_t s = 0; s < shapelets.size(); s++) c.bb.setShapeletParent(s, l);
		double ignored = 0;
		c.ctx.refitInPlace(l, ignored);
		return l;
	};
	test::ContextOnBoard b(P);
	const Id l = makeBoard(b);
	const auto logp = [&](const Pose& p) {
		return logJointAt(b.bb, b.bb.leg(l), p, [&](const model::Leg& to) { b.bb.setLeg(l, to); });
	};
	const Moments exact = quadrature(logp, poseOf(b.bb.leg(l)));
	const inference::SamplerParams rj = reversibleJump(exact);
	const inference::Acceptance acceptance(rj.acceptance);
	for (const bool drop : {false, true})
	{
		test::ContextOnBoard run(P);
		makeBoard(run);
		MoveContext ctx(run.bb, run.P, rj, run.rng, acceptance);
		ctx.result = &run.result;
		inference::moves::LegRefit move;
		const Moments m = chain(
			ctx, move, [&] { return move.propose(ctx, l); }, [&] { return poseOf(run.bb.leg(l)); }, STEPS, drop);
		const std::string what = std::string("free leg refit") + (drop ? ", reverse dropped" : "");
		EXPECT_EQ(matches(m, exact, what), !drop) << what;
	}
}

namespace
{
/** A board under stochastic refits, with a leg `from` holding 2+ contacts moved 2 mm off its
 *  fit (where the deterministic refits declare no reverse). False if the board has none. */
struct OffFitBoard
{
	explicit OffFitBoard(uint64_t seed) : b(seed, seed % 2), ctx(b.bb, b.P, rj(), b.rng, acceptance)
	{
		ctx.result = &b.result;
		for (const Id l : b.legs())
			if (b.bb.shapeletsOf(l).size() >= 2) from = l;
		if (from == NONE) return;
		model::Leg off = b.bb.leg(from);
		off.x += 0.002;
		b.bb.setLeg(from, off);
	}
	static const inference::SamplerParams& rj()
	{
		static const inference::SamplerParams params = [] {
			inference::SamplerParams p;
			p.acceptance = inference::AcceptanceRule::ReversibleJump;
			return p;
		}();
		return params;
	}

	MoveBoard b;
	const inference::Acceptance acceptance{inference::AcceptanceRule::ReversibleJump};
	MoveContext ctx;
	Id from = NONE;
};

/** log density of drawing leg l's pose `pose` on board `bb` as it is (its own context). */
double logRefit(const MoveBoard& like, model::Blackboard bb, Id l, const model::Leg& pose)
{
	inference::SamplerRandom rng;
	const inference::Acceptance acceptance;
	MoveContext ctx(bb, like.P, OffFitBoard::rj(), rng, acceptance);
	return ctx.logRefitTo(l, pose);
}
}  // namespace

// A contact moves from a leg off its fit to another leg nearby (a leg split off the same
// touch): both legs are drawn about their fits, the proposal's densities are those of the new
// poses about the fits before and of the old poses about the fits of the reverse link, and a
// rejection restores the board.
TEST(StochasticRefits, LinkFromALegOffItsFitHasAReverse)
{
	int checked = 0;
	for (uint64_t seed = 0; seed < 240; seed++)
	{
		OffFitBoard o(seed);
		if (o.from == NONE) continue;
		const std::vector<Id> own(o.b.bb.shapeletsOf(o.from).begin(), o.b.bb.shapeletsOf(o.from).end());
		inference::moves::SplitMerge split;
		split.split(o.ctx, static_cast<size_t>(own[0]));
		split.finish(o.ctx, true);
		const Id to = o.b.bb.shapeletParent(static_cast<size_t>(own[0]));
		const auto s = static_cast<size_t>(own[1]);
		if (own.size() == 2 && o.b.bb.leg(o.from).parent == NONE) continue;  // the link would drop `from`
		const model::Blackboard before = o.b.bb;
		model::Blackboard linked = before;  // the fits the forward move draws about
		linked.setShapeletParent(s, to);
		inference::moves::ShapeletLink move;
		const Proposal p = move.link(o.ctx, s, to, inference::Move::Child);
		EXPECT_NEAR(model::logJoint(o.b.bb) - model::logJoint(before), p.logTarget, 1e-7) << seed;
		const double forward =
			logRefit(o.b, linked, to, o.b.bb.leg(to)) + logRefit(o.b, linked, o.from, o.b.bb.leg(o.from));
		model::Blackboard back = o.b.bb;  // the fits the reverse link draws about
		back.setShapeletParent(s, o.from);
		const double reverse = logRefit(o.b, back, to, before.leg(to)) + logRefit(o.b, back, o.from, before.leg(o.from));
		move.finish(o.ctx, false);
		test::expectSameBoard(before, o.b.bb, "rejected link");
		if (!std::isfinite(forward))  // a leg without a valid fit stays, and nothing can reverse that
		{
			EXPECT_EQ(p.logReverse, -std::numeric_limits<double>::infinity()) << seed;
			continue;
		}
		EXPECT_NEAR(p.logForward, forward, 1e-9) << seed;
		EXPECT_TRUE(std::isfinite(p.logReverse)) << seed;
		EXPECT_NEAR(p.logReverse, reverse, 1e-9) << seed;
		checked++;
	}
	EXPECT_GE(checked, 20);
}

// Split a contact off a leg that is off its fit, then merge it back: each declares its reverse
// (the deterministic refits declared none here) and scores the exact change of logJoint.
TEST(StochasticRefits, SplitAndMergeOfALegOffItsFitHaveReverses)
{
	int checked = 0;
	for (uint64_t seed = 0; seed < 120; seed++)
	{
		OffFitBoard o(seed);
		if (o.from == NONE) continue;
		const auto& own = o.b.bb.shapeletsOf(o.from);
		const auto s = static_cast<size_t>(own[o.b.pick(own.size())]);
		const model::Blackboard before = o.b.bb;
		inference::moves::SplitMerge move;
		const Proposal split = move.split(o.ctx, s);
		EXPECT_NEAR(model::logJoint(o.b.bb) - model::logJoint(before), split.logTarget, 1e-7) << seed;
		EXPECT_TRUE(std::isfinite(split.logReverse)) << seed;
		move.finish(o.ctx, true);
		const Id other = o.b.bb.shapeletParent(s);
		const model::Blackboard afterSplit = o.b.bb;
		const auto merge = move.merge(o.ctx, o.from, other);
		if (!merge) continue;  // the merged leg's fit leaves the gate
		EXPECT_NEAR(model::logJoint(o.b.bb) - model::logJoint(afterSplit), merge->logTarget, 1e-7) << seed;
		EXPECT_TRUE(std::isfinite(merge->logReverse)) << seed;
		move.finish(o.ctx, false);
		test::expectSameBoard(afterSplit, o.b.bb, "rejected merge");
		checked++;
	}
	EXPECT_GE(checked, 30);
}
