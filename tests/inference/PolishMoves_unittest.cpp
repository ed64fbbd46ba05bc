// The polish's sliding table and contact exchange (doc/sampler.md, "Moves"): each on the
// situation it is for, against the move it improves on, and on random boards: logTarget is
// the change of logJoint, and a rejected proposal leaves the board as it was.
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/TableProposals.h>
#include <whiskermap/inference/moves/ContactExchange.h>
#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/inference/moves/SlidingTableBirth.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>

#include "MoveBoards.h"

using namespace whiskermap;
using inference::moves::Proposal;
using model::Id;
using model::NONE;
using test::MoveBoard;

namespace
{
/** A board of `shapelets` and a context on it (no random draws needed). */
struct Board : test::ContextOnBoard
{
	explicit Board(const std::vector<obs::Shapelet>& shapelets) { bb.reset(shapelets); }
	/** A free leg of the default width and texture at (x, y, theta) explaining `shapelets`. */
	Id leg(double x, double y, double theta, std::initializer_list<size_t> shapelets)
	{
		model::Leg l;
		l.x = x, l.y = y, l.theta = theta, l.wx = l.wy = P.leg_width, l.texture = P.texture;
		const Id id = bb.addLeg(l);
		for (const size_t s : shapelets) bb.setShapeletParent(s, id);
		return id;
	}
};
}  // namespace

// Two touched legs of a table, one contact each on their outer long faces: each leg may stand
// anywhere along its face. Slid 2 cm outward (where a birth may have put them), their table
// fitted to the pair leaves each 2 cm off its corner and loses to no table; with the legs
// slid to the corners it wins, at the true pose.
TEST(PolishMoves, SlidingTableFindsTheTableOfTwoSlidLegs)
{
	const model::ModelParams P;
	const model::Table truth{0.3, -0.2, 0.4, P.leg_width, P.texture};
	Board b(test::touchTable(truth, P, {{0, 1, 0.0}, {1, 1, 0.0}}));
	double x0, y0, x1, y1;
	model::tableCorner(truth, 0, P, x0, y0);
	model::tableCorner(truth, 1, P, x1, y1);
	const double ux = std::cos(truth.theta) * 0.02, uy = std::sin(truth.theta) * 0.02;  // 2 cm along the length
	const Id a = b.leg(x0 + ux, y0 + uy, truth.theta, {0});
	b.leg(x1 - ux, y1 - uy, truth.theta, {1});
	std::vector<model::Table> tables;
	inference::moves::SlidingTableBirth::candidates(b.ctx, a, tables);
	ASSERT_EQ(tables.size(), 2u);  // the table and its mirror image across the pair
	const double before = model::logJoint(b.bb);
	double best = -1e9, plainBest = -1e9;
	model::Table found;
	for (const model::Table& t : tables)
	{
		inference::moves::TableBirthDeath plain(P);
		const Proposal q = plain.birthOf(b.ctx, a, t);
		plain.finish(b.ctx, false);
		plainBest = std::max(plainBest, q.logTarget);
		inference::moves::SlidingTableBirth sliding(P);
		const Proposal p = sliding.propose(b.ctx, a, t);
		EXPECT_NEAR(model::logJoint(b.bb) - before, p.logTarget, 1e-7);
		EXPECT_FALSE(std::isfinite(p.logReverse));
		if (p.logTarget > best) best = p.logTarget, found = b.bb.table(b.bb.leg(a).parent);
		sliding.finish(b.ctx, false);
		EXPECT_NEAR(model::logJoint(b.bb), before, 1e-9);
		EXPECT_EQ(b.bb.tableCount(), 0u);
	}
	EXPECT_LT(plainBest, 0);
	EXPECT_GT(best, 3);
	EXPECT_NEAR(found.x, truth.x, 2e-3);
	EXPECT_NEAR(found.y, truth.y, 2e-3);
	EXPECT_NEAR(std::remainder(found.theta - truth.theta, M_PI), 0, 0.01);
}

// Three contacts along one face line (a wall): two 1 cm apart and a third 7 cm from them. The
// leg holding the far one and the middle one spreads wider than a face; the middle contact
// belongs with its near neighbour. A link refits only the leg it joins: the leg left behind
// keeps its pose, its contact past its face's end, and overlaps the other. The exchange refits
// both and gains more (measured: 2.0 nats against the link's 1.0).
TEST(PolishMoves, ExchangeRefitsTheLegTheContactLeaves)
{
	const model::ModelParams P;
	std::vector<obs::Shapelet> s(3);
	const double xs[3] = {0.0, 0.07, 0.08};
	for (size_t i = 0; i < 3; i++) s[i] = {xs[i], 0.0, M_PI_2, P.texture, static_cast<int>(i)};
	Board b(s);
	const Id wide = b.leg(0.035, -P.leg_width / 2, 0, {0, 1});
	const Id near = b.leg(0.09, -P.leg_width / 2, 0, {2});
	for (const Id l : {wide, near})
	{
		double ignored = 0;
		b.ctx.refitInPlace(l, ignored);
	}
	const double before = model::logJoint(b.bb);
	inference::moves::ShapeletLink link;
	const Proposal linked = link.link(b.ctx, 1, near, inference::Move::Child);
	link.finish(b.ctx, false);
	EXPECT_NEAR(model::logJoint(b.bb), before, 1e-9);
	inference::moves::ContactExchange exchange;
	const auto p = exchange.propose(b.ctx, 1, near);
	ASSERT_TRUE(p);
	EXPECT_NEAR(model::logJoint(b.bb) - before, p->logTarget, 1e-7);
	EXPECT_GT(p->logTarget, 0);
	EXPECT_GT(p->logTarget, linked.logTarget + 0.5);
	exchange.finish(b.ctx, true);
	EXPECT_EQ(b.bb.shapeletParent(1), near);
	EXPECT_EQ(b.bb.shapeletParent(0), wide);
	// Nothing would stay on the leg of contact 0 now: no exchange (that is a merge).
	EXPECT_FALSE(exchange.propose(b.ctx, 0, near));
}

// On random boards: the exact change of logJoint, and a rejection restores the board.
TEST(PolishMoves, LogTargetIsTheChangeOfLogJointAndRejectionRestores)
{
	int slides = 0, exchanges = 0;
	for (uint64_t seed = 0; seed < 120; seed++)
	{
		MoveBoard b(seed, seed % 2);
		for (const Id l : b.legs())
		{
			std::vector<model::Table> tables;
			inference::moves::SlidingTableBirth::candidates(b.ctx, l, tables);
			for (const model::Table& t : tables)
			{
				const model::Blackboard saved = b.bb;
				const double before = model::logJoint(b.bb);
				inference::moves::SlidingTableBirth move(b.P);
				const Proposal p = move.propose(b.ctx, l, t);
				EXPECT_NEAR(model::logJoint(b.bb) - before, p.logTarget, 1e-7) << seed;
				move.finish(b.ctx, false);
				EXPECT_NEAR(model::logJoint(b.bb), before, 1e-9) << seed;
				test::expectSameBoard(saved, b.bb, "sliding table, rejected");
				slides++;
			}
		}
		// A neighbour: one contact of a leg holding two or more split off to a new free leg.
		Id from = NONE;
		for (const Id l : b.legs())
			if (b.bb.shapeletsOf(l).size() >= 2) from = l;
		if (from == NONE) continue;
		const auto first = static_cast<size_t>(b.bb.shapeletsOf(from)[0]);
		const Id to = b.bb.addLeg(b.ctx.newLegFor(first));
		b.bb.setShapeletParent(first, to);
		for (size_t s = 0; s < b.bb.shapelets().size(); s++)
			{
				const model::Blackboard saved = b.bb;
				const double before = model::logJoint(b.bb);
				inference::moves::ContactExchange move;
				const auto p = move.propose(b.ctx, s, to);
				if (!p) continue;
				EXPECT_NEAR(model::logJoint(b.bb) - before, p->logTarget, 1e-7) << seed;
				move.finish(b.ctx, false);
				EXPECT_NEAR(model::logJoint(b.bb), before, 1e-9) << seed;
				test::expectSameBoard(saved, b.bb, "exchange, rejected");
				exchanges++;
			}
	}
	EXPECT_GE(slides, 100);  // measured 504
	EXPECT_GE(exchanges, 10);  // measured 18
}

// The polish moves are the per-pose step's: the lasting map's anneal never proposes them (in
// its insertions they cost tactile SLAM its track, doc/sampler.md "Polish moves").
TEST(PolishMoves, OnlyThePerPoseStepOffersThem)
{
	const model::ModelParams P;
	// Two free legs 9 cm apart, each touched on two adjacent faces, their facing faces 4 cm
	// apart: each leg's contacts are within the parent gate of the other (exchanges offered).
	const double w = P.leg_width / 2;
	const std::vector<obs::Shapelet> shapelets{
		{0, w, M_PI_2, P.texture, 0}, {w, 0, 0, P.texture, 1}, {0.09, w, M_PI_2, P.texture, 2}, {0.09 - w, 0, M_PI, P.texture, 3}};
	inference::BlackboardSampler sampler(P, inference::SamplerParams{});
	const auto offered = [](const inference::StepResult& r) {
		uint64_t n = 0;
		for (const auto& t : r.moveTypes)
			if (t.name == std::string("sliding table for leg") || t.name == std::string("contact exchange")) n += t.proposed;
		return n;
	};
	uint64_t stepped = 0;
	for (uint64_t seed = 0; seed < 5; seed++) stepped += offered(sampler.step(shapelets, seed));
	EXPECT_GT(stepped, 0u);
	model::Blackboard start(P);
	start.reset(shapelets);
	for (uint64_t seed = 0; seed < 5; seed++) EXPECT_EQ(offered(sampler.anneal(start, seed)), 0u) << seed;
}
