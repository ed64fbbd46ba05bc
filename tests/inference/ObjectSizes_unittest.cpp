// Object sizes (issue 11; doc/model.md, "Object sizes", eq. 24): the size prior, the corners
// of a resized table, the closed-form size fit, the resize move's exact logTarget, and the
// sampler inferring an off-size table's size.
#include <gtest/gtest.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/moves/TableRefit.h>
#include <whiskermap/model/Posterior.h>

#include "MoveBoards.h"
#include "SyntheticTable.h"

using namespace whiskermap;
using model::ModelParams;
using model::Table;

namespace
{
/** One class, the paper's 1.0 x 0.6 table, size_sigma 2 cm; size moves on. */
ModelParams sized()
{
	ModelParams p;
	model::ObjectClass table;
	table.size_sigma = 0.02;
	p.classes = {table};
	p.size_moves = true;
	return p;
}
}  // namespace

TEST(ObjectSizes, SizePriorAndCornersUseTheTablesOwnSize)
{
	const ModelParams p = sized();
	Table t{0, 0, 0, 0.05, 0.7};
	EXPECT_EQ(model::logSizePrior(t, p), 0.0);  // the nominal size costs nothing more
	t.d_length = 0.02, t.d_width = -0.01;
	// eq. 24: -(0.02^2 + 0.01^2) / (2 x 0.02^2) = -0.625
	EXPECT_NEAR(model::logSizePrior(t, p), -0.625, 1e-12);
	EXPECT_NEAR(model::logTablePrior(t, p) - model::logTablePrior(Table{0, 0, 0, 0.05, 0.7}, p), -0.625, 1e-12);
	EXPECT_NEAR(p.lengthOf(t), 1.02, 1e-15);
	EXPECT_NEAR(p.widthOf(t), 0.59, 1e-15);
	double x = 0, y = 0;
	model::tableCorner(t, 0, p, x, y);  // corner 0: (+length/2, +width/2)
	EXPECT_NEAR(x, 0.51, 1e-15);
	EXPECT_NEAR(y, 0.295, 1e-15);
	EXPECT_NEAR(model::tableRect(t, p).hx, 0.51, 1e-15);
	// Without a catalogue there is no size term.
	EXPECT_EQ(model::logSizePrior(t, ModelParams{}), 0.0);
}

TEST(ObjectSizes, SizeFitHandComputed)
{
	// Legs exactly at the corners of a 1.1 x 0.65 table (centre (1, 2), yaw 0.3), fitted from
	// the nominal 1.0 x 0.6 table at the same pose. Per axis, with w = 1 / sigma_corner^2 =
	// 1e4 and k = 1 / size_sigma^2 = 2500, four legs, two per side: the centre stays and the
	// spacing is (w b_legs + k b_nominal) / (w + k): length (1.1e4 + 2500) / 12500 = 1.08,
	// width (0.65e4 + 0.6 x 2500) / 12500 = 0.64.
	const ModelParams p = sized();
	Table truth{1, 2, 0.3, 0.05, 0.7};
	truth.d_length = 0.1, truth.d_width = 0.05;
	model::Leg legs[4];
	const model::Leg* ptr[4];
	int corners[4];
	for (int i = 0; i < 4; i++)
	{
		model::tableCorner(truth, i, p, legs[i].x, legs[i].y);
		ptr[i] = &legs[i], corners[i] = i;
	}
	const Table fit = inference::fitTableSize(p, Table{1, 2, 0.3, 0.05, 0.7}, ptr, corners, 4);
	EXPECT_NEAR(fit.x, 1, 1e-12);
	EXPECT_NEAR(fit.y, 2, 1e-12);
	EXPECT_EQ(fit.theta, 0.3);
	EXPECT_NEAR(p.lengthOf(fit), 1.08, 1e-12);
	EXPECT_NEAR(p.widthOf(fit), 0.64, 1e-12);
	// Legs on one side only (corners 0 and 3: +x): the length stays nominal, the centre moves
	// to put that side on the legs: the legs' +x side at 0.55, so the centre shifts by 0.05.
	const Table side = inference::fitTableSize(p, Table{1, 2, 0.3, 0.05, 0.7}, std::vector<const model::Leg*>{ptr[0], ptr[3]}.data(),
											   std::vector<int>{0, 3}.data(), 2);
	EXPECT_NEAR(side.d_length, 0, 1e-12);
	EXPECT_NEAR((side.x - 1) * std::cos(0.3) + (side.y - 2) * std::sin(0.3), 0.05, 1e-12);
}

TEST(ObjectSizes, ResizeLogTargetIsTheChangeOfTheJoint)
{
	const ModelParams p = sized();
	int resized = 0;
	for (uint64_t seed = 0; seed < 30; seed++)
	{
		test::MoveBoard b(seed, true, p);
		const double before = model::logJoint(b.bb);
		inference::moves::TableRefit move(true);
		const auto prop = move.propose(b.ctx, b.table);
		if (!prop) continue;
		move.finish(b.ctx, true);
		EXPECT_NEAR(model::logJoint(b.bb) - before, prop->logTarget, 1e-7) << seed;
		resized += b.bb.table(b.table).d_length != 0 || b.bb.table(b.table).d_width != 0;
	}
	EXPECT_GT(resized, 10);
}

TEST(ObjectSizes, SamplerInfersTheSizeOfAnOffSizeTable)
{
	// A 1.03 x 0.62 table (1.5 and 1 size_sigma off the class's 1.0 x 0.6), touched twice on
	// each of its four legs. With size moves the MAP table's size moves more than half way from
	// the class's to the truth, never past it: eq. 24 pulls it towards the nominal size, and
	// eq. 6 pulls each leg (two contacts) towards its corner, so the mode is about 1.022 x
	// 0.615 (each leg's data weighs 1 / (sigma_corner^2 + sigma_r^2 / 2) against the prior's
	// 1 / size_sigma^2). Without size moves it keeps the class's size, 3 and 2 cm off.
	ModelParams p = sized();
	Table truth{0.4, -0.2, 0.5, 0.05, 0.7};
	truth.d_length = 0.03, truth.d_width = 0.02;
	const auto shapelets = test::touchTable(
		truth, p, {{0, 0, 0.01}, {0, 1, -0.01}, {1, 1, 0}, {1, 2, 0.01}, {2, 2, 0}, {2, 3, -0.01}, {3, 3, 0}, {3, 0, 0.01}});
	for (int seed = 0; seed < 5; seed++)
	{
		const inference::StepResult r = inference::BlackboardSampler(p, inference::SamplerParams{}).step(shapelets, seed);
		ASSERT_EQ(r.map.tables.size(), 1u) << "seed " << seed;
		const double length = p.lengthOf(r.map.tables[0]), width = p.widthOf(r.map.tables[0]);
		EXPECT_GT(length, 1.015) << "seed " << seed;
		EXPECT_LE(length, 1.03) << "seed " << seed;
		EXPECT_GT(width, 0.61) << "seed " << seed;
		EXPECT_LE(width, 0.62) << "seed " << seed;
		EXPECT_LT(std::hypot(r.map.tables[0].x - truth.x, r.map.tables[0].y - truth.y), 0.005) << "seed " << seed;
	}
	p.size_moves = false;
	const inference::StepResult fixed = inference::BlackboardSampler(p, inference::SamplerParams{}).step(shapelets, 1);
	ASSERT_EQ(fixed.map.tables.size(), 1u);
	EXPECT_EQ(p.lengthOf(fixed.map.tables[0]), 1.0);
	EXPECT_EQ(p.widthOf(fixed.map.tables[0]), 0.6);
}
