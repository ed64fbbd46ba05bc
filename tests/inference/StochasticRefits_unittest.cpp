// Stochastic refits under the reversible-jump acceptance (doc/sampler.md, "Stochastic
// refits"): on continuous poses, a chain of one refit move at beta = 1 samples the model's
// posterior of the pose it moves (its mean and variance against quadrature of exp(logJoint)),
// and fails to when the move's reverse density is dropped; the links, splits and merges that
// refit legs declare their reverse wherever the leg they leave stays, and score the exact
// change of logJoint.
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/inference/moves/SplitMerge.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/inference/moves/TableRefit.h>

#include "MoveBoards.h"

#include <array>
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

namespace
{
using Pose = std::array<double, 3>;  // x, y, yaw

struct Moments
{
	Pose mean{}, var{};
	double logIntegral = 0;  ///< log of the integral of exp(logp) over the pose (quadrature only)
};

/** Posterior mean and variance of a pose with log density `logp` (up to a constant) by
 *  quadrature: a grid of n^3 points over +-7 standard deviations of the Laplace approximation
 *  at `mode` along its Cholesky axes (so correlated coordinates are covered too). */
Moments quadrature(const std::function<double(const Pose&)>& logp, const Pose& mode, int n = 61)
{
	double H[3][3];  // minus the Hessian, by central differences
	const double h[3] = {1e-4, 1e-4, 1e-4};
	const auto at = [&](int a, double da, int b, double db) {
		Pose p = mode;
		p[a] += da, p[b] += db;
		return logp(p);
	};
	for (int a = 0; a < 3; a++)
		for (int b = 0; b < 3; b++)
			H[a][b] = -(at(a, h[a], b, h[b]) - at(a, h[a], b, -h[b]) - at(a, -h[a], b, h[b]) + at(a, -h[a], b, -h[b])) /
					  (4 * h[a] * h[b]);
	double L[3][3] = {};  // H = L L^T
	for (int i = 0; i < 3; i++)
		for (int j = 0; j <= i; j++)
		{
			double sum = H[i][j];
			for (int k = 0; k < j; k++) sum -= L[i][k] * L[j][k];
			L[i][j] = i == j ? std::sqrt(sum) : sum / L[j][j];
		}
	// p = mode + L^-T z: solve L^T d = z (back substitution).
	const auto offset = [&](const Pose& z) {
		Pose d{};
		for (int i = 2; i >= 0; i--)
		{
			double sum = z[static_cast<size_t>(i)];
			for (int k = i + 1; k < 3; k++) sum -= L[k][i] * d[static_cast<size_t>(k)];
			d[static_cast<size_t>(i)] = sum / L[i][i];
		}
		return d;
	};
	const double top = logp(mode);
	double w = 0;
	Pose m1{}, m2{};
	for (int i = 0; i < n; i++)
		for (int j = 0; j < n; j++)
			for (int k = 0; k < n; k++)
			{
				const auto z = [&](int q) { return -7 + 14.0 * q / (n - 1); };
				const Pose d = offset({z(i), z(j), z(k)});
				Pose p = mode;
				for (size_t a = 0; a < 3; a++) p[a] += d[a];
				const double wi = std::exp(logp(p) - top);
				w += wi;
				for (size_t a = 0; a < 3; a++) m1[a] += wi * p[a], m2[a] += wi * p[a] * p[a];
			}
	Moments out;
	for (size_t a = 0; a < 3; a++) out.mean[a] = m1[a] / w, out.var[a] = m2[a] / w - out.mean[a] * out.mean[a];
	const double dz = 14.0 / (n - 1);  // the grid's volume element: dz^3 / det L
	out.logIntegral = top + std::log(w) + 3 * std::log(dz) - std::log(L[0][0] * L[1][1] * L[2][2]);
	return out;
}

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

/** The pose of a table or leg. */
template <class H>
Pose poseOf(const H& h)
{
	return {h.x, h.y, h.theta};
}

/** logJoint of `bb` with a table or leg (now `current`) moved to pose p by `set`, then set back. */
template <class H, class Set>
double logJointAt(const model::Blackboard& bb, const H& current, const Pose& p, Set&& set)
{
	const H old = current;
	H moved = old;
	moved.x = p[0], moved.y = p[1], moved.theta = p[2];
	set(moved);
	const double out = model::logJoint(bb);
	set(old);
	return out;
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
	model::ModelParams P;
	P.alpha_S = 300;  // a contact's leg about as probable as none (the defaults give 1 - 1e-4)
	const model::Table t{0.3, -0.2, 0.4, P.leg_width, P.texture};
	const auto shapelets = test::touchTable(t, P, {{0, 0, 0.004}});
	inference::SamplerParams broad;
	broad.acceptance = inference::AcceptanceRule::ReversibleJump;
	broad.proposals = inference::Proposals::Broad;
	const inference::Acceptance acceptance(broad.acceptance);

	// Exact: odds = sum over the grid of exp(logOddsLeg) * (area, yaw) element / (2 delta)^3.
	test::ContextOnBoard q(P);
	q.bb.reset(shapelets);
	const obs::Shapelet& s = shapelets[0];
	model::Leg leg;
	leg.wx = leg.wy = P.leg_width, leg.texture = s.texture;
	const Id l = q.bb.addLeg(leg);
	q.bb.setShapeletParent(0, l);
	const int NR = 60, NPHI = 120, NYAW = 180;
	const double w = P.leg_width, cell = std::pow(2 * P.delta, 3);
	double odds = 0;
	for (int i = 0; i < NR; i++)
		for (int j = 0; j < NPHI; j++)
			for (int k = 0; k < NYAW; k++)
			{
				const double r = w * (i + 0.5) / NR, phi = 2 * M_PI * (j + 0.5) / NPHI;
				leg.x = s.x + r * std::cos(phi), leg.y = s.y + r * std::sin(phi), leg.theta = 2 * M_PI * (k + 0.5) / NYAW;
				q.bb.setLeg(l, leg);
				odds += std::exp(model::logOddsLeg(q.bb, l)) * r * (w / NR) * (2 * M_PI / NPHI) * (2 * M_PI / NYAW) / cell;
			}
	const double exact = odds / (1 + odds);
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
		return logJointAt(b.bb, b.bb.table(t), p, [&](const model::Table& to) { b.bb.setTable(t, to); }) - without;
	};
	moments = quadrature(logp, poseOf(ThreeLegs::TRUTH));
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
