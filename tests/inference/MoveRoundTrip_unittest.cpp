// Round trips of the sampler's moves (doc/sampler.md, "Moves"): on random small boards, a move
// and then its declared reverse give back the same board, and the two Proposals' changes of
// logJoint and log proposal ratios are negatives of each other. Each move's logTarget is also
// checked against logJoint itself.
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/inference/moves/MoveRegistry.h>
#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/inference/moves/SplitMerge.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/inference/moves/TableRefit.h>

#include "MoveBoards.h"

#include <algorithm>
#include <limits>

using namespace whiskermap;
using inference::moves::Proposal;
using model::Id;
using model::NONE;
using test::MoveBoard;

namespace
{
constexpr uint64_t BOARDS = 60;

/** Runs `propose` on b's board, keeps the move, and checks logTarget against logJoint. */
template <class M, class Propose>
Proposal applied(MoveBoard& b, M& move, Propose&& propose)
{
	const double before = model::logJoint(b.bb);
	const Proposal p = propose();
	move.finish(b.ctx, true);
	EXPECT_NEAR(model::logJoint(b.bb) - before, p.logTarget, 1e-7);
	return p;
}

/** The leg added since `before` (the ids live then). */
Id newLeg(const MoveBoard& b, const std::vector<Id>& before)
{
	for (const Id l : b.legs())
		if (std::find(before.begin(), before.end(), l) == before.end()) return l;
	return NONE;
}
}  // namespace

TEST(MoveRoundTrip, FreeLegBirthThenDeath)
{
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, seed % 2);
		const size_t s = b.pick(b.bb.shapelets().size());
		b.bb.setShapeletParent(s, NONE);  // priming: a shapelet without a leg
		const model::Blackboard before = b.bb;
		inference::moves::LegBirthDeath move;
		const Proposal birth = applied(b, move, [&] { return move.birthFor(b.ctx, s); });
		const Id born = b.bb.shapeletParent(s);
		const Proposal death = applied(b, move, [&] { return *move.death(b.ctx, born); });
		ASSERT_TRUE(std::isfinite(death.logReverse)) << seed;
		test::expectReverses(birth, death, "birth, death");
		test::expectSameBoard(before, b.bb, "birth, death");
	}
}

TEST(MoveRoundTrip, CornerLegBirthThenDeath)
{
	int tried = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, true);
		const model::Blackboard before = b.bb;
		const std::vector<Id> legs = b.legs();
		inference::moves::LegBirthDeath move;
		const auto birth = move.birthAtCorner(b.ctx, b.table);
		if (!birth) continue;
		move.finish(b.ctx, true);
		const Proposal death = applied(b, move, [&] { return *move.death(b.ctx, newLeg(b, legs)); });
		test::expectReverses(*birth, death, "corner birth, death");
		test::expectSameBoard(before, b.bb, "corner birth, death");
		tried++;
	}
	EXPECT_GE(tried, static_cast<int>(BOARDS) / 2);
}

TEST(MoveRoundTrip, SplitThenMerge)
{
	int tried = 0;
	for (uint64_t seed = 0; seed < 4 * BOARDS; seed++)
	{
		MoveBoard b(seed, true);
		Id from = NONE;
		for (const Id l : b.legs())
			if (b.bb.shapeletsOf(l).size() >= 2) from = l;
		if (from == NONE) continue;
		const auto& own = b.bb.shapeletsOf(from);
		const auto s = static_cast<size_t>(own[b.pick(own.size())]);
		if (seed % 2)
		{
			model::Leg off = b.bb.leg(from);  // 2 mm off its fit: the merge cannot put it back
			off.x += 0.002;
			b.bb.setLeg(from, off);
		}
		const model::Blackboard before = b.bb;
		inference::moves::SplitMerge move;
		const Proposal split = applied(b, move, [&] { return move.split(b.ctx, s); });
		EXPECT_EQ(std::isfinite(split.logReverse), seed % 2 == 0) << seed;
		if (seed % 2) continue;  // no reverse claimed
		const Id other = b.bb.shapeletParent(s);
		const double afterSplit = model::logJoint(b.bb);
		const auto merge = move.merge(b.ctx, from, other);
		ASSERT_TRUE(merge.has_value()) << seed;
		move.finish(b.ctx, true);
		EXPECT_NEAR(model::logJoint(b.bb) - afterSplit, merge->logTarget, 1e-7);
		test::expectReverses(split, *merge, "split, merge");
		test::expectSameBoard(before, b.bb, "split, merge");
		tried++;
	}
	EXPECT_GE(tried, 10);
}

// The reverse is drawn among candidates: seeds are tried until it draws the old parent.
TEST(MoveRoundTrip, ReparentThenBack)
{
	int tried = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, true);
		model::Table shifted = b.bb.table(b.table);
		shifted.x += 0.01;
		b.bb.addTable(shifted);  // a second table whose corners are within the gate of the legs
		const Id l = b.legs()[b.pick(b.legs().size())];
		const model::Blackboard before = b.bb;
		inference::moves::LegReparent move;
		const Proposal forward = applied(b, move, [&] { return *move.propose(b.ctx, l); });
		const model::Blackboard after = b.bb;
		bool back = false;
		for (uint64_t r = 0; r < 50 && !back; r++)
		{
			b.bb = after;
			b.rng.seed(r);
			const Proposal reverse = applied(b, move, [&] { return *move.propose(b.ctx, l); });
			back = b.bb.leg(l).parent == before.leg(l).parent;
			if (back) test::expectReverses(forward, reverse, "reparent, back");
		}
		ASSERT_TRUE(back) << seed;
		test::expectSameBoard(before, b.bb, "reparent, back");
		tried++;
	}
	EXPECT_EQ(tried, static_cast<int>(BOARDS));
}

// Table death declares no reverse density (doc/sampler.md), so only the board and the change
// of logJoint are compared.
TEST(MoveRoundTrip, TableBirthThenDeath)
{
	int tried = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, false);
		const model::Blackboard before = b.bb;
		inference::moves::TableBirthDeath move(b.P);
		const Id l = b.legs()[b.pick(b.legs().size())];
		const Proposal birth = applied(b, move, [&] { return move.birth(b.ctx, l); });
		ASSERT_TRUE(std::isfinite(birth.logReverse)) << seed;  // free legs, nothing removed
		const Proposal death = applied(b, move, [&] { return move.death(b.ctx, b.bb.leg(l).parent); });
		EXPECT_NEAR(birth.logTarget + death.logTarget, 0, 1e-9);
		test::expectSameBoard(before, b.bb, "table birth, death");
		tried++;
	}
	EXPECT_EQ(tried, static_cast<int>(BOARDS));
}

// Every move's logTarget is the exact change of logJoint (applied() checks it), for the moves
// without a round trip too: links (with their refit and drop), leg and table refits. (Births,
// deaths, splits, merges, reparents and table births are checked in the round trips above.)
TEST(MoveRoundTrip, LogTargetIsTheChangeOfLogJoint)
{
	int links = 0, legRefits = 0, tableRefits = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, seed % 2);
		const std::vector<Id> legs = b.legs();
		const auto s = b.pick(b.bb.shapelets().size());
		const Id to = legs[b.pick(legs.size())];
		if (b.bb.shapeletParent(s) != to)
		{
			inference::moves::ShapeletLink move;
			applied(b, move, [&] { return move.link(b.ctx, s, to, inference::Move::Child); });
			links++;
		}
		for (int i = 0; i < 2; i++)  // the second time at the fit: a zero change
		{
			inference::moves::LegRefit move;
			const Id l = b.legs()[0];
			if (!move.propose(b.ctx, l)) continue;
			move.finish(b.ctx, false);
			applied(b, move, [&] { return *move.propose(b.ctx, l); });
			legRefits++;
		}
		inference::moves::TableRefit move;
		if (b.table == NONE || !move.propose(b.ctx, b.table)) continue;
		move.finish(b.ctx, false);
		applied(b, move, [&] { return *move.propose(b.ctx, b.table); });
		tableRefits++;
	}
	EXPECT_GE(links, 10);
	EXPECT_GE(legRefits, 10);
	EXPECT_GE(tableRefits, 5);
}

namespace
{
/** Every hypothesis of the board, its pose and links, and logJoint: equal when nothing changed. */
std::vector<double> state(const model::Blackboard& bb)
{
	std::vector<double> out{model::logJoint(bb)};
	for (Id t = 0; t < bb.tableIdBound(); t++)
		if (bb.hasTable(t)) out.insert(out.end(), {double(t), bb.table(t).x, bb.table(t).y, bb.table(t).theta});
	for (Id l = 0; l < bb.legIdBound(); l++)
		if (bb.hasLeg(l))
			out.insert(out.end(), {double(l), bb.leg(l).x, bb.leg(l).y, bb.leg(l).theta, bb.leg(l).wx, double(bb.leg(l).parent)});
	for (size_t s = 0; s < bb.shapelets().size(); s++) out.push_back(bb.shapeletParent(s));
	for (Id w = 0; w < bb.wallIdBound(); w++) out.push_back(bb.hasWall(w));
	return out;
}
}  // namespace

// The sampler scores the board at a checkpoint only when a move was accepted since the last
// score (BlackboardSampler::checkpoint): every registered move, offered to every hypothesis at
// a finite and at an infinite beta, leaves the board exactly as it was (logJoint to the bit)
// when it counts no acceptance.
TEST(MoveRoundTrip, AMoveThatCountsNoAcceptanceLeavesTheBoardAsItWas)
{
	int unchanged = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		model::ModelParams params;
		params.walls = seed % 3 == 2;
		MoveBoard b(seed, seed % 2, params);
		const inference::moves::MoveRegistry registry(b.P);
		for (const double beta : {1.0, std::numeric_limits<double>::infinity()})
		{
			b.ctx.beta = beta;
			b.ctx.searchPoses = true;
			for (const inference::moves::MoveEntry& e : registry.entries())
			{
				const Id bound = e.target == inference::moves::Target::Table  ? b.bb.tableIdBound()
								 : e.target == inference::moves::Target::Leg  ? b.bb.legIdBound()
								 : e.target == inference::moves::Target::Wall ? b.bb.wallIdBound()
																			  : static_cast<Id>(b.bb.shapelets().size());
				for (Id id = 0; id < bound; id++)
				{
					const bool alive = e.target == inference::moves::Target::Table  ? b.bb.hasTable(id)
									   : e.target == inference::moves::Target::Leg  ? b.bb.hasLeg(id)
									   : e.target == inference::moves::Target::Wall ? b.bb.hasWall(id)
																					: !b.bb.explained(static_cast<size_t>(id));
					if (!alive) continue;
					const auto accepted = [&] {
						uint64_t n = 0;
						for (const uint32_t a : b.result.accepted) n += a;
						return n;
					};
					const uint64_t acceptedBefore = accepted();
					const std::vector<double> before = state(b.bb);
					e.visit(b.ctx, id);
					if (accepted() != acceptedBefore) continue;
					EXPECT_EQ(state(b.bb), before) << e.name << " on " << id << ", board " << seed << ", beta " << beta;
					unchanged++;
				}
			}
		}
	}
	EXPECT_GE(unchanged, 1000);
}

// Under the reversible-jump acceptance a leg refit is stochastic (doc/sampler.md, "Moves"):
// the fit plus Gaussian noise. Its forward density is that of the new pose about the fit from
// the old board, its reverse that of the old pose about the fit from the new board, computed
// here independently; so the move from the new board back to the old one has exactly the
// negated log ratio. logTarget is the change of logJoint; a rejection restores the board.
TEST(MoveRoundTrip, StochasticLegRefitUnderReversibleJump)
{
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	const auto logDensity = [&](const model::Leg& leg, const model::Leg& fit) {
		const double sp = rj.leg_position_noise, sa = rj.leg_angle_noise;
		const double dx = leg.x - fit.x, dy = leg.y - fit.y, da = std::remainder(leg.theta - fit.theta, 2 * M_PI);
		return -0.5 * (dx * dx + dy * dy) / (sp * sp) - 0.5 * da * da / (sa * sa) - 2 * std::log(sp * std::sqrt(2 * M_PI)) -
			   std::log(sa * std::sqrt(2 * M_PI));
	};
	int checked = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, seed % 2);
		inference::moves::MoveContext ctx(b.bb, b.P, rj, b.rng, b.acceptance);
		ctx.result = &b.result;
		const Id l = b.legs()[b.pick(b.legs().size())];
		const model::Leg old = b.bb.leg(l);
		const model::Table* t = old.parent == NONE ? nullptr : &b.bb.table(old.parent);
		model::Leg fit;
		if (!ctx.fittedLeg(l, t, fit)) continue;
		const double before = model::logJoint(b.bb);
		inference::moves::LegRefit move;
		const auto p = move.propose(ctx, l);
		ASSERT_TRUE(p.has_value());
		const model::Leg drawn = b.bb.leg(l);
		EXPECT_NEAR(model::logJoint(b.bb) - before, p->logTarget, 1e-7);
		EXPECT_NEAR(p->logForward, logDensity(drawn, fit), 1e-9);
		model::Leg back;
		ASSERT_TRUE(ctx.fittedLeg(l, t, back));
		EXPECT_NEAR(p->logReverse, logDensity(old, back), 1e-9);
		EXPECT_TRUE(std::isfinite(p->logReverse));
		move.finish(ctx, false);
		EXPECT_EQ(b.bb.leg(l).x, old.x);
		EXPECT_EQ(b.bb.leg(l).theta, old.theta);
		EXPECT_NEAR(model::logJoint(b.bb), before, 1e-12);
		checked++;
	}
	EXPECT_GE(checked, 40);
}

// With zero refit noise the stochastic refit is the closed form: its densities are point
// masses (0 at the fit, -inf elsewhere), never NaN (which the acceptance would take for 1).
TEST(MoveRoundTrip, StochasticLegRefitWithZeroNoiseIsAPointMass)
{
	inference::SamplerParams rj;
	rj.acceptance = inference::AcceptanceRule::ReversibleJump;
	rj.leg_position_noise = rj.leg_angle_noise = 0;
	int checked = 0;
	for (uint64_t seed = 0; seed < BOARDS; seed++)
	{
		MoveBoard b(seed, seed % 2);
		inference::moves::MoveContext ctx(b.bb, b.P, rj, b.rng, b.acceptance);
		ctx.result = &b.result;
		inference::moves::LegRefit move;
		const auto p = move.propose(ctx, b.legs()[0]);
		if (!p) continue;
		EXPECT_EQ(p->logForward, 0);
		EXPECT_FALSE(std::isnan(p->logReverse));
		EXPECT_TRUE(p->logReverse == 0 || p->logReverse == -std::numeric_limits<double>::infinity()) << p->logReverse;
		move.finish(ctx, false);
		checked++;
	}
	EXPECT_GE(checked, 40);
}
