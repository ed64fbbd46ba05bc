// Leg width and texture per object (issue 11; doc/model.md "Leg width and texture", eq. 26):
// the prior by hand, the leg fit's exact logTarget, and the sampler inferring the leg width
// and texture of a table whose legs are not its class's.
#include <gtest/gtest.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/moves/TableLegFit.h>
#include <whiskermap/model/Posterior.h>

#include "MoveBoards.h"
#include "SyntheticTable.h"

using namespace whiskermap;
using model::ModelParams;
using model::Table;

namespace
{
/** One class, the paper's 1.0 x 0.6 table with 5 cm legs of texture 0.7; leg width spread
 *  1 cm, texture spread 0.1; size moves on. */
ModelParams varied()
{
	ModelParams p;
	model::ObjectClass table;
	table.leg_width_sigma = 0.01;
	table.texture_sigma = 0.1;
	p.classes = {table};
	p.size_moves = true;
	return p;
}
}  // namespace

TEST(LegDimensions, LegPriorHandComputed)
{
	const ModelParams p = varied();
	Table t{0, 0, 0, 0.05, 0.7};
	EXPECT_EQ(model::logLegPrior(t, p), 0.0);
	EXPECT_TRUE(p.legsVary());
	t.leg_width = 0.06, t.texture = 0.6;
	// eq. 26: -(0.01^2) / (2 x 0.01^2) - (0.1^2) / (2 x 0.1^2) = -1
	EXPECT_NEAR(model::logLegPrior(t, p), -1.0, 1e-12);
	EXPECT_NEAR(model::logTablePrior(t, p) - model::logTablePrior(Table{0, 0, 0, 0.05, 0.7}, p), -1.0, 1e-12);
	// A class without spreads has no such term (its tables keep its legs).
	ModelParams fixed = p;
	fixed.classes[0].leg_width_sigma = fixed.classes[0].texture_sigma = 0;
	EXPECT_FALSE(fixed.legsVary());
	EXPECT_EQ(model::logLegPrior(t, fixed), 0.0);
	// One spread only: its own term.
	fixed.classes[0].texture_sigma = 0.1;
	EXPECT_NEAR(model::logLegPrior(t, fixed), -0.5, 1e-12);
}

TEST(LegDimensions, LegFitLogTargetIsTheChangeOfTheJoint)
{
	const ModelParams p = varied();
	int changed = 0;
	for (uint64_t seed = 0; seed < 30; seed++)
	{
		test::MoveBoard b(seed, true, p);
		const double before = model::logJoint(b.bb);
		inference::moves::TableLegFit move;
		const auto prop = move.propose(b.ctx, b.table);
		if (!prop) continue;
		move.finish(b.ctx, true);
		EXPECT_NEAR(model::logJoint(b.bb) - before, prop->logTarget, 1e-7) << seed;
		const Table& t = b.bb.table(b.table);
		changed += t.leg_width != 0.05 || t.texture != 0.7;
		for (const model::Id l : b.bb.legsOf(b.table))  // its legs have its leg width
			EXPECT_EQ(b.bb.leg(l).wx, t.leg_width) << seed;
		// Rejected, the board is as before.
		test::MoveBoard c(seed, true, p);
		const double start = model::logJoint(c.bb);
		inference::moves::TableLegFit again;
		if (again.propose(c.ctx, c.table)) again.finish(c.ctx, false);
		EXPECT_EQ(model::logJoint(c.bb), start) << seed;
	}
	EXPECT_GT(changed, 10);
}

TEST(LegDimensions, SamplerInfersTheLegWidthAndTextureOfATable)
{
	// A table with 7 cm legs of texture 0.55 (2 and 1.5 spreads off its class's 5 cm, 0.7),
	// each leg touched on two opposite faces and one more: the opposite faces fix the width,
	// the contacts' textures the texture. Each mode is the data's pulled back by eq. 26: the
	// width's, with each opposite pair (w - 0.07)^2 / (2 sigma_r^2) (each face 0.07 - w / 2
	// off) over four legs, weight 2 / 0.01^2 = 20000 against 1 / (2 x 0.01^2) = 5000:
	// (20000 x 0.07 + 5000 x 0.05) / 25000 = 0.066, less eq. 7's normaliser along the faces
	// (doc/model.md): -12 log(w + sqrt(pi) sigma_r) over the 12 contacts, all within their faces'
	// ends, moves the mode to the root of 50000 (w - 0.066) = -12 / (w + 0.01772): 0.0630
	// (0.066 without it). The texture's, weight 50 against four
	// legs' 4 x (3/4) / 0.1^2 = 300 (a leg's texture is the mean of its table's and its three
	// contacts'): (50 x 0.7 + 300 x 0.55) / 350 = 0.571. Without the spreads the table keeps
	// its class's legs.
	ModelParams p = varied();
	Table truth{0.4, -0.2, 0.5, 0.07, 0.55};
	std::vector<test::Touch> touches;
	for (int corner = 0; corner < 4; corner++)
		for (const int face : {corner, corner + 2, corner + 1}) touches.push_back({corner, face % 4, 0.005 * (face - corner)});
	const auto shapelets = test::touchTable(truth, p, touches);
	for (int seed = 0; seed < 5; seed++)
	{
		const inference::StepResult r = inference::BlackboardSampler(p, inference::SamplerParams{}).step(shapelets, seed);
		ASSERT_EQ(r.map.tables.size(), 1u) << "seed " << seed;
		EXPECT_NEAR(r.map.tables[0].leg_width, 0.0630, 0.001) << "seed " << seed;
		EXPECT_NEAR(r.map.tables[0].texture, 0.571, 0.02) << "seed " << seed;
		EXPECT_LT(std::hypot(r.map.tables[0].x - truth.x, r.map.tables[0].y - truth.y), 0.005) << "seed " << seed;
	}
	p.classes[0].leg_width_sigma = p.classes[0].texture_sigma = 0;
	const inference::StepResult fixed = inference::BlackboardSampler(p, inference::SamplerParams{}).step(shapelets, 1);
	ASSERT_EQ(fixed.map.tables.size(), 1u);
	EXPECT_EQ(fixed.map.tables[0].leg_width, 0.05);
	EXPECT_EQ(fixed.map.tables[0].texture, 0.7);
}

TEST(LegDimensions, ALegIsNeverWiderThanHalfTheSmallerLegSpacing)
{
	// A small class (0.2 x 0.12 m spacings, 4 cm legs) with a broad spread (0.5 m), its four
	// legs each explaining two contacts on opposite faces 10 cm apart: the data want 10 cm
	// legs; repeated leg fits climb to half the smaller spacing, 6 cm, and stop there.
	ModelParams p;
	model::ObjectClass small;
	small.name = small.label = "stool";
	small.length = 0.2, small.width = 0.12, small.leg_width = 0.04, small.texture = 0.7;
	small.leg_width_sigma = 0.5;
	p.classes = {small};
	p.size_moves = true;
	const Table truth{0, 0, 0.3, 0.1, 0.7};
	std::vector<test::Touch> touches;
	for (int corner = 0; corner < 4; corner++)
		for (const int face : {0, 2}) touches.push_back({corner, face, 0});
	test::ContextOnBoard b(p);
	b.bb.reset(test::touchTable(truth, p, touches));
	Table start = truth;
	start.leg_width = 0.04;
	const model::Id table = b.bb.addTable(start);
	for (int corner = 0; corner < 4; corner++)
	{
		model::Leg leg;
		model::tableCorner(start, corner, p, leg.x, leg.y);
		leg.theta = start.theta, leg.wx = leg.wy = 0.04, leg.texture = 0.7, leg.parent = table;
		const model::Id l = b.bb.addLeg(leg);
		for (size_t s = 0; s < touches.size(); s++)
			if (touches[s].corner == corner) b.bb.setShapeletParent(s, l);
	}
	double widest = 0;
	for (int k = 0; k < 30; k++)
	{
		inference::moves::TableLegFit move;
		if (move.propose(b.ctx, table)) move.finish(b.ctx, true);
		widest = std::max(widest, b.bb.table(table).leg_width);
	}
	EXPECT_LE(widest, 0.06 + 1e-12);
	EXPECT_GT(b.bb.table(table).leg_width, 0.059);  // it did climb: without the bound it would pass 6 cm
}
