// Object classes (issue 11; doc/model.md, "Object classes"): the class switch move's round
// trip, and the sampler telling a chair-sized leg square from a table.
#include <gtest/gtest.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/inference/moves/TableClassSwitch.h>

#include "MoveBoards.h"
#include "SyntheticTable.h"

using namespace whiskermap;
using inference::moves::Proposal;
using model::ModelParams;
using model::Table;

namespace
{
/** The paper's table as class 0 (so MoveBoard's table is one), a desk and a chair. */
ModelParams withClasses()
{
	ModelParams p;
	model::ObjectClass table, desk, chair;
	table.prior = 0.5;
	desk.name = desk.label = "desk", desk.length = 1.4, desk.width = 0.7, desk.texture = 0.6, desk.prior = 0.3;
	chair.name = chair.label = "chair", chair.length = chair.width = 0.42, chair.leg_width = 0.03, chair.texture = 0.5;
	chair.prior = 0.2;
	p.classes = {table, desk, chair};
	return p;
}
}  // namespace

TEST(TableClassSwitch, SwitchThenBackRestoresTheBoard)
{
	const ModelParams params = withClasses();
	int changed = 0;
	for (uint64_t seed = 0; seed < 40; seed++)
	{
		test::MoveBoard b(seed, true, params);
		const model::Blackboard before = b.bb;
		const double joint = model::logJoint(b.bb);
		inference::moves::TableClassSwitch move;
		const auto there = move.propose(b.ctx, b.table);
		ASSERT_TRUE(there.has_value());
		move.finish(b.ctx, true);
		const int to = b.bb.table(b.table).cls;
		ASSERT_NE(to, 0) << seed;
		EXPECT_EQ(b.bb.table(b.table).leg_width, params.legWidthOf(to));
		EXPECT_EQ(b.bb.table(b.table).texture, params.textureOf(to));
		EXPECT_NEAR(model::logJoint(b.bb) - joint, there->logTarget, 1e-7) << seed;
		EXPECT_NEAR(there->logForward, std::log(0.5), 1e-12);
		changed += there->logTarget != 0;
		const Proposal back = move.switchTo(b.ctx, b.table, 0);
		move.finish(b.ctx, true);
		EXPECT_EQ(b.bb.table(b.table).cls, 0);
		test::expectReverses(*there, back, "class switch, back");
		test::expectSameBoard(before, b.bb, "class switch, back");
		EXPECT_NEAR(model::logJoint(b.bb), joint, 1e-7) << seed;
	}
	EXPECT_EQ(changed, 40);  // another class always changes the joint (its prior, its corners)
}

TEST(TableClassSwitch, RejectedSwitchLeavesTheBoardAndNoCatalogueProposesNothing)
{
	test::MoveBoard b(3, true, withClasses());
	const model::Blackboard before = b.bb;
	inference::moves::TableClassSwitch move;
	ASSERT_TRUE(move.propose(b.ctx, b.table).has_value());
	move.finish(b.ctx, false);
	test::expectSameBoard(before, b.bb, "rejected switch");
	EXPECT_EQ(b.bb.table(b.table).cls, 0);
	test::MoveBoard plain(3, true);
	EXPECT_FALSE(move.propose(plain.ctx, plain.table).has_value());
}

TEST(ObjectClasses, ChairSizedLegSquareIsAChair)
{
	// Three touched legs of a chair (0.42 m square, 3 cm legs, texture 0.5): no table, desk or
	// other size fits their spacing, so the MAP is one chair with its legs at its corners.
	const ModelParams p = withClasses();
	Table chair{0.8, -0.3, 0.4, 0.03, 0.5};
	chair.cls = 2;
	const auto shapelets = test::touchTable(chair, p, {{0, 0, 0.005}, {0, 1, 0}, {1, 1, -0.005}, {2, 2, 0}, {2, 3, 0}});
	inference::BlackboardSampler sampler(p, inference::SamplerParams{});
	for (int seed = 0; seed < 5; seed++)
	{
		const inference::StepResult r = sampler.step(shapelets, seed);
		ASSERT_EQ(r.map.tables.size(), 1u) << "seed " << seed;
		const Table& t = r.map.tables[0];
		EXPECT_EQ(t.cls, 2) << "seed " << seed;
		EXPECT_EQ(t.leg_width, 0.03);
		EXPECT_LT(std::hypot(t.x - chair.x, t.y - chair.y), 0.01) << "seed " << seed;
		for (const model::Leg& l : r.map.legs)
			if (l.parent != model::NONE)
			{
				EXPECT_EQ(l.wx, 0.03) << "seed " << seed;  // refitted at the chair's leg width
			}
	}
	// The same square under the model without a catalogue (one 1.0 x 0.6 table) is no table.
	const ModelParams one;
	const inference::StepResult r = inference::BlackboardSampler(one, inference::SamplerParams{}).step(shapelets, 1);
	for (const Table& t : r.map.tables) EXPECT_GT(std::hypot(t.x - chair.x, t.y - chair.y), 0.05);
}

TEST(ObjectClasses, BirthResizesAdoptedLegsAndItsLogTargetIsExact)
{
	// Classes whose leg widths (4 and 3 cm) differ from the board's 5 cm free legs: a table
	// birth refits the legs it adopts at its width, and logTarget is still the exact change.
	ModelParams params = withClasses();
	params.classes[0].leg_width = 0.04;
	int resized = 0;
	for (uint64_t seed = 0; seed < 30; seed++)
	{
		test::MoveBoard b(seed, false, params);
		const std::vector<model::Id> legs = b.legs();
		inference::moves::TableBirthDeath move(params);
		const double before = model::logJoint(b.bb);
		const Proposal p = move.birth(b.ctx, legs[b.pick(legs.size())]);
		move.finish(b.ctx, true);
		EXPECT_NEAR(model::logJoint(b.bb) - before, p.logTarget, 1e-7) << seed;
		for (const model::Id l : b.legs())
		{
			const model::Leg& leg = b.bb.leg(l);
			if (leg.parent == model::NONE || leg.wx == 0.05) continue;
			EXPECT_EQ(leg.wx, b.bb.table(leg.parent).leg_width) << seed;
			resized++;
		}
	}
	EXPECT_GT(resized, 10);
}
