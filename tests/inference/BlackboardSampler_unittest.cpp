#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>

#include "SyntheticTable.h"

using namespace whiskermap;
using inference::BlackboardSampler;
using inference::Move;
using inference::SamplerParams;
using inference::StepResult;
using model::ModelParams;
using model::NONE;
using model::Table;
using test::touchTable;

namespace
{
const ModelParams P;
const Table truth{1.3, -0.4, 0.5, P.leg_width, P.texture};
constexpr int SEEDS = 10;

// Touched legs of `t` at `corners` within `metres` of some corner of `table`.
int cornersMatched(const Table& table, const std::vector<int>& corners, double metres)
{
	int n = 0;
	for (const int c : corners)
	{
		double tx = 0, ty = 0;
		model::tableCorner(truth, c, P, tx, ty);
		for (int i = 0; i < 4; i++)
		{
			double x = 0, y = 0;
			model::tableCorner(table, i, P, x, y);
			if (std::hypot(x - tx, y - ty) <= metres)
			{
				n++;
				break;
			}
		}
	}
	return n;
}

// Every hypothesis left explains a shapelet directly or shares a table with one that does.
void expectPruned(const model::HypothesisSet& h)
{
	std::vector<bool> legExplains(h.legs.size(), false), tableExplains(h.tables.size(), false);
	for (const model::Id l : h.shapeletParent)
		if (l != NONE) legExplains[l] = true;
	for (size_t l = 0; l < h.legs.size(); l++)
		if (legExplains[l] && h.legs[l].parent != NONE) tableExplains[h.legs[l].parent] = true;
	for (size_t t = 0; t < h.tables.size(); t++) EXPECT_TRUE(tableExplains[t]) << "table " << t;
	for (size_t l = 0; l < h.legs.size(); l++)
		EXPECT_TRUE(legExplains[l] || (h.legs[l].parent != NONE && tableExplains[h.legs[l].parent]))
			<< "leg " << l;
}
}  // namespace

TEST(BlackboardSampler, NoShapeletsGiveAnEmptyResult)
{
	BlackboardSampler sampler(P, SamplerParams{});
	const StepResult r = sampler.step({}, 42, 0);
	EXPECT_TRUE(r.map.tables.empty());
	EXPECT_TRUE(r.map.legs.empty());
	EXPECT_EQ(r.logPosterior, 0);
	for (size_t m = 0; m < inference::MOVE_COUNT; m++) EXPECT_EQ(r.proposed[m], 0u);
	ASSERT_TRUE(r.snapshot.has_value());
	EXPECT_TRUE(r.snapshot->legs.empty());
}

TEST(BlackboardSampler, SameSeedSameResult)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {1, 1, -0.01}, {2, 3, 0.0}, {2, 2, 0.01}});
	BlackboardSampler a(P, SamplerParams{}), b(P, SamplerParams{});
	int differing = 0;
	for (uint64_t seed = 0; seed < 5; seed++)
	{
		const StepResult ra = a.step(shapelets, seed, 3), rb = b.step(shapelets, seed, 3);
		const StepResult again = a.step(shapelets, seed, 3);  // a sampler reused is still equal
		for (const StepResult* r : {&rb, &again})
		{
			EXPECT_EQ(ra.logPosterior, r->logPosterior);
			EXPECT_EQ(ra.proposed, r->proposed);
			EXPECT_EQ(ra.accepted, r->accepted);
			ASSERT_EQ(ra.map.tables.size(), r->map.tables.size());
			for (size_t t = 0; t < ra.map.tables.size(); t++)
			{
				EXPECT_EQ(ra.map.tables[t].x, r->map.tables[t].x);
				EXPECT_EQ(ra.map.tables[t].theta, r->map.tables[t].theta);
			}
			ASSERT_EQ(ra.map.legs.size(), r->map.legs.size());
			for (size_t l = 0; l < ra.map.legs.size(); l++) EXPECT_EQ(ra.map.legs[l].y, r->map.legs[l].y);
			EXPECT_EQ(ra.map.shapeletParent, r->map.shapeletParent);
			EXPECT_EQ(ra.snapshot->legs.size(), r->snapshot->legs.size());
		}
		differing += a.step(shapelets, seed + 100).proposed != ra.proposed;
	}
	EXPECT_GT(differing, 0);  // the seed matters
}

TEST(BlackboardSampler, ThreeTouchedLegsGiveTheTable)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {1, 1, -0.01}, {2, 3, 0.0}});
	BlackboardSampler sampler(P, SamplerParams{});
	for (int seed = 0; seed < SEEDS; seed++)
	{
		const StepResult r = sampler.step(shapelets, seed);
		ASSERT_EQ(r.map.tables.size(), 1u) << "seed " << seed;
		const Table& t = r.map.tables[0];
		EXPECT_LT(std::hypot(t.x - truth.x, t.y - truth.y), 0.03) << "seed " << seed;
		EXPECT_LT(std::abs(core::angleDiff(t.theta, truth.theta, M_PI)), core::deg2rad(3)) << "seed " << seed;
		EXPECT_EQ(cornersMatched(t, {0, 1, 2}, P.parent_gate), 3);
		EXPECT_GT(r.logPosterior, 0);  // beats the empty explanation (7 * log c_S < 0)
		expectPruned(r.map);
		EXPECT_GT(r.acceptedOf(Move::Parent), 0u);
	}
}

// Two legs along one side: the table and its mirror image across that side explain the
// contacts equally well (paper section 6: "ambiguous poses"). Either is right; nothing else.
TEST(BlackboardSampler, TwoTouchedLegsGiveTheTableOrItsMirror)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {0, 1, -0.01}, {1, 1, 0.0}, {1, 2, 0.02}});
	BlackboardSampler sampler(P, SamplerParams{});
	for (int seed = 0; seed < SEEDS; seed++)
	{
		const StepResult r = sampler.step(shapelets, seed);
		ASSERT_EQ(r.map.tables.size(), 1u) << "seed " << seed;
		EXPECT_EQ(cornersMatched(r.map.tables[0], {0, 1}, 0.03), 2) << "seed " << seed;
		expectPruned(r.map);
	}
}

// One touched leg: a table is not worth it (doc/model.md). At most one table may appear,
// and only with a corner at that leg; the leg found must be the touched one.
TEST(BlackboardSampler, OneTouchedLegInventsNothingElsewhere)
{
	const auto shapelets = touchTable(truth, P, {{3, 0, 0.01}, {3, 3, -0.01}});
	BlackboardSampler sampler(P, SamplerParams{});
	int withoutTable = 0;
	for (int seed = 0; seed < SEEDS; seed++)
	{
		const StepResult r = sampler.step(shapelets, seed);
		ASSERT_LE(r.map.tables.size(), 1u);
		if (r.map.tables.empty()) withoutTable++;
		else EXPECT_EQ(cornersMatched(r.map.tables[0], {3}, 0.03), 1);
		double x = 0, y = 0;
		model::tableCorner(truth, 3, P, x, y);
		ASSERT_NE(r.map.shapeletParent[0], NONE);
		const model::Leg& l = r.map.legs[r.map.shapeletParent[0]];
		EXPECT_LT(std::hypot(l.x - x, l.y - y), 0.015);
		expectPruned(r.map);
	}
	EXPECT_GE(withoutTable, SEEDS / 2);
}

TEST(BlackboardSampler, SnapshotOnlyWhenAsked)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {1, 1, -0.01}});
	BlackboardSampler sampler(P, SamplerParams{});
	EXPECT_FALSE(sampler.step(shapelets, 1).snapshot.has_value());
	const auto last = static_cast<int>(sampler.params().schedule.size()) - 1;
	const StepResult r = sampler.step(shapelets, 1, last);
	ASSERT_TRUE(r.snapshot.has_value());
	EXPECT_EQ(r.snapshot->shapeletParent.size(), shapelets.size());
	EXPECT_FALSE(r.snapshot->legs.empty());
}

// Refit (PoseFit.h): a leg with contacts on two faces, placed 2 cm off, comes back within
// 2 mm of the true leg; a table from a pair of legs at two corners lands within 1 cm, 1 deg.
TEST(PoseFit, LegRefitFromTwoCentimetresOff)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {0, 1, -0.005}});
	double x = 0, y = 0;
	model::tableCorner(truth, 0, P, x, y);
	const obs::Shapelet* contacts[2] = {&shapelets[0], &shapelets[1]};
	// Free leg (weak pull from a start 2 cm off) and leg under its table (pull to the corner).
	const model::Leg free = inference::fitLeg(P, contacts, 2, nullptr, x + 0.02, y - 0.01, 1e-3);
	EXPECT_LT(std::hypot(free.x - x, free.y - y), 0.002);
	EXPECT_LT(std::abs(core::angleDiff(free.theta, truth.theta, M_PI_2)), 1e-9);
	const model::Leg linked = inference::fitLeg(P, contacts, 2, &truth, x, y, 1);
	EXPECT_LT(std::hypot(linked.x - x, linked.y - y), 0.002);
	// One contact leaves the leg free along its face: the corner pull slides it home.
	const model::Leg one = inference::fitLeg(P, contacts, 1, &truth, x, y, 1);
	EXPECT_LT(std::hypot(one.x - x, one.y - y), 0.002);
}

// The same contacts folded into a leg's evidence (LegEvidence) fit the leg as they do
// one by one: the lasting map keeps its legs where all their contacts put them.
TEST(PoseFit, FoldedContactsFitLikeExplicitOnes)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {0, 1, -0.005}, {0, 0, -0.008}});
	double x = 0, y = 0;
	model::tableCorner(truth, 0, P, x, y);
	const obs::Shapelet* contacts[3] = {&shapelets[0], &shapelets[1], &shapelets[2]};
	const model::Leg explicitFit = inference::fitLeg(P, contacts, 3, nullptr, x + 0.02, y - 0.01, 1e-3);
	model::Leg start = explicitFit;
	start.x += 0.004, start.theta += 0.03;  // folded while the leg was a little off
	model::LegEvidence folded;
	for (const auto& s : shapelets) folded.add(s, start, P);
	const model::Leg foldedFit = inference::fitLeg(P, nullptr, 0, nullptr, x + 0.02, y - 0.01, 1e-3, &folded);
	EXPECT_LT(std::hypot(foldedFit.x - explicitFit.x, foldedFit.y - explicitFit.y), 1e-4);
	EXPECT_LT(std::abs(core::angleDiff(foldedFit.theta, explicitFit.theta, M_PI_2)), 1e-6);
	EXPECT_NEAR(foldedFit.texture, explicitFit.texture, 1e-9);
	// Half folded, half explicit: the same again.
	model::LegEvidence half;
	half.add(shapelets[0], start, P);
	const model::Leg mixed = inference::fitLeg(P, contacts + 1, 2, nullptr, x + 0.02, y - 0.01, 1e-3, &half);
	EXPECT_LT(std::hypot(mixed.x - explicitFit.x, mixed.y - explicitFit.y), 1e-4);
}

TEST(PoseFit, TableFromTwoLegs)
{
	for (int pair = 0; pair < 3; pair++)
	{
		const int corners[2] = {0, pair + 1};
		model::Leg a, b;
		model::tableCorner(truth, corners[0], P, a.x, a.y);
		model::tableCorner(truth, corners[1], P, b.x, b.y);
		a.theta = truth.theta + 0.05, b.theta = truth.theta - 0.03;  // yaws a little off
		b.x += 0.004;
		const model::Leg* legs[2] = {&a, &b};
		const Table start{0, 0, 0, P.leg_width, P.texture};
		const Table t = inference::fitTable(P, start, legs, corners, 2);
		EXPECT_LT(std::hypot(t.x - truth.x, t.y - truth.y), 0.01) << "pair " << pair;
		EXPECT_LT(std::abs(core::angleDiff(t.theta, truth.theta, M_PI)), core::deg2rad(1)) << "pair " << pair;
	}
}

// End to end: contacts on three legs, each placed from one contact, give the table within
// 1 cm and 1 deg on every seed (the refit moves; before them, 3 cm and 3 deg).
TEST(BlackboardSampler, RefitPlacesTheTable)
{
	const auto shapelets =
		touchTable(truth, P, {{0, 0, 0.015}, {0, 1, -0.01}, {1, 1, 0.02}, {2, 3, -0.015}, {2, 2, 0.01}});
	BlackboardSampler sampler(P, SamplerParams{});
	for (int seed = 0; seed < SEEDS; seed++)
	{
		const StepResult r = sampler.step(shapelets, seed);
		ASSERT_EQ(r.map.tables.size(), 1u) << "seed " << seed;
		const Table& t = r.map.tables[0];
		EXPECT_LT(std::hypot(t.x - truth.x, t.y - truth.y), 0.01) << "seed " << seed;
		EXPECT_LT(std::abs(core::angleDiff(t.theta, truth.theta, M_PI)), core::deg2rad(1)) << "seed " << seed;
		EXPECT_GT(r.acceptedOf(Move::Refit), 0u);
		expectPruned(r.map);
	}
}

// The greedy polish removes a table that one touched leg cannot pay for (doc/model.md: -9.2
// nats): with one touched leg, no seed keeps a table.
TEST(BlackboardSampler, PolishDropsOneLegTables)
{
	const auto shapelets = touchTable(truth, P, {{3, 0, 0.01}, {3, 3, -0.01}});
	BlackboardSampler sampler(P, SamplerParams{});
	for (int seed = 0; seed < SEEDS; seed++) EXPECT_TRUE(sampler.step(shapelets, seed).map.tables.empty()) << seed;
}

// The broad baseline (doc/sampler.md, "Broad proposals"): a new leg anywhere within a leg
// width of its contact, at any yaw, with the density LegBirthDeath declares; the data-driven
// one puts the contact on the face of matching normal.
TEST(BlackboardSampler, BroadNewLegsLieAnywhereNearTheirContact)
{
	const obs::Shapelet s{0.4, -0.2, 0.3, P.texture, 0};
	model::Blackboard bb(P);
	bb.reset({s});
	SamplerParams broad;
	broad.proposals = inference::Proposals::Broad;
	const inference::Acceptance acceptance(broad.acceptance);
	inference::SamplerRandom rng;
	rng.seed(7);
	inference::moves::MoveContext ctx(bb, P, broad, rng, acceptance);
	const double w = P.leg_width;
	int yawBins[4] = {0, 0, 0, 0}, inner = 0;
	constexpr int DRAWS = 4000;
	for (int i = 0; i < DRAWS; i++)
	{
		const model::Leg l = ctx.newLegFor(0);
		const double d = std::hypot(l.x - s.x, l.y - s.y);
		ASSERT_LE(d, w);
		inner += d < w / 2;  // a quarter of the disc's area
		yawBins[static_cast<int>((core::wrapToPi(l.theta) + M_PI) / M_PI_2) % 4]++;
		EXPECT_DOUBLE_EQ(inference::moves::LegBirthDeath::logBirthDensity(ctx, 0, l),
						 -std::log(M_PI * w * w) - std::log(2 * M_PI));
	}
	EXPECT_NEAR(inner, DRAWS / 4, 4 * std::sqrt(DRAWS * 0.25 * 0.75));
	for (const int n : yawBins) EXPECT_NEAR(n, DRAWS / 4, 4 * std::sqrt(DRAWS * 0.25 * 0.75));

	SamplerParams dataDriven;
	inference::moves::MoveContext face(bb, P, dataDriven, rng, acceptance);
	for (int i = 0; i < 100; i++)
	{
		const model::Leg l = face.newLegFor(0);
		// The centre half a width behind the contact along its normal (3 mm noise).
		EXPECT_NEAR((s.x - l.x) * std::cos(s.normal) + (s.y - l.y) * std::sin(s.normal), w / 2, 0.015);
	}
}

// With broad proposals nothing is fitted and the polish searches no pose; a chain 20 times
// longer still finds the table of three touched legs, less exactly.
TEST(BlackboardSampler, BroadProposalsSearchNoPoseAndStillFindTheTable)
{
	const auto shapelets = touchTable(truth, P, {{0, 0, 0.01}, {1, 1, -0.01}, {2, 3, 0.0}});
	SamplerParams broad;
	broad.proposals = inference::Proposals::Broad;
	broad.sweeps_per_temperature *= 20;
	broad.coldest_sweeps *= 20;
	BlackboardSampler b(P, broad), d(P, SamplerParams{});
	int found = 0;
	double gap = 0;
	for (int seed = 0; seed < SEEDS; seed++)
	{
		const StepResult rb = b.step(shapelets, seed), rd = d.step(shapelets, seed);
		EXPECT_EQ(rb.poseEvaluations, 0u);
		EXPECT_GT(rd.poseEvaluations, 0u);
		EXPECT_LE(rb.logPosterior, rd.logPosterior + 0.5) << "seed " << seed;
		expectPruned(rb.map);
		found += rb.map.tables.size() == 1 && cornersMatched(rb.map.tables[0], {0, 1, 2}, 0.03) == 3;
		gap += rd.logPosterior - rb.logPosterior;
	}
	EXPECT_GE(found, SEEDS - 2);
	EXPECT_GT(gap / SEEDS, 0.5);  // measured: 2.5 nats below on average (0.6 to 7.2)
}
