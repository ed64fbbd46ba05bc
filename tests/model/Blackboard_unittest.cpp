#include <gtest/gtest.h>
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Densities.h>

#include <algorithm>
#include <random>

using namespace whiskermap::model;

namespace
{
Leg squareLeg(double x, double y, Id parent = NONE)
{
	return {x, y, 0, 0.05, 0.05, 0.5, parent, -1};
}
}  // namespace

TEST(Blackboard, LinksFollowRemovalAndIdsAreStable)
{
	ModelParams p;
	Blackboard bb(p);
	bb.reset({{0.5, 0.3, 0, 0.5, 0}, {-0.5, 0.3, 0, 0.5, 1}});
	const Id t = bb.addTable({0, 0, 0, p.leg_width, p.texture});
	const Id a = bb.addLeg(squareLeg(0.5, 0.3, t));
	const Id b = bb.addLeg(squareLeg(-0.5, -0.3, t));
	EXPECT_EQ(bb.leg(a).corner, 0);
	EXPECT_EQ(bb.leg(b).corner, 2);
	EXPECT_EQ(bb.cornerCounts(t), (CornerCounts{1, 0, 1, 0}));
	EXPECT_EQ(bb.cornerCounts(t, a), (CornerCounts{0, 0, 1, 0}));
	bb.setShapeletParent(0, a);
	bb.setShapeletParent(1, b);

	bb.removeLeg(a);
	EXPECT_FALSE(bb.hasLeg(a));
	EXPECT_EQ(bb.shapeletParent(0), NONE);
	EXPECT_EQ(bb.shapeletParent(1), b);  // untouched
	EXPECT_EQ(bb.leg(b).parent, t);

	bb.removeTable(t);
	EXPECT_EQ(bb.leg(b).parent, NONE);
	EXPECT_EQ(bb.leg(b).corner, -1);
	EXPECT_EQ(bb.tableCount(), 0u);
	EXPECT_EQ(bb.legCount(), 1u);

	const Id c = bb.addLeg(squareLeg(3, 3));  // reuses a's slot; b keeps its id
	EXPECT_EQ(c, a);
	EXPECT_TRUE(bb.hasLeg(b));
	EXPECT_EQ(bb.leg(b).x, -0.5);
}

TEST(Blackboard, NearQueriesMatchBruteForce)
{
	ModelParams p;
	Blackboard bb(p);
	bb.reset({});
	std::mt19937_64 rng(7);
	std::uniform_real_distribution<double> u(-3, 3);
	for (int i = 0; i < 300; i++) bb.addLeg(squareLeg(u(rng), u(rng)));
	for (Id i = 0; i < 300; i += 3) bb.removeLeg(i);  // hash must forget removed legs
	for (int q = 0; q < 100; q++)
	{
		const double x = u(rng), y = u(rng), r = q % 2 ? 0.07 : 0.9;
		std::vector<Id> found, expected;
		bb.forEachLegNear(x, y, r, [&](Id id) { found.push_back(id); });
		for (Id id = 0; id < bb.legIdBound(); id++)
			if (bb.hasLeg(id) && std::hypot(bb.leg(id).x - x, bb.leg(id).y - y) <= r)
				expected.push_back(id);
		std::sort(found.begin(), found.end());
		EXPECT_EQ(found, expected);
	}
}

TEST(Blackboard, CompactRenumbersLinks)
{
	ModelParams p;
	Blackboard bb(p);
	bb.reset({{0, 0, 0, 0.5, 0}});
	const Id t0 = bb.addTable({5, 5, 0, p.leg_width, p.texture});
	const Id t1 = bb.addTable({0, 0, 0, p.leg_width, p.texture});
	const Id l0 = bb.addLeg(squareLeg(9, 9));
	const Id l1 = bb.addLeg(squareLeg(-0.5, 0.3, t1));
	bb.setShapeletParent(0, l1);
	bb.removeTable(t0);
	bb.removeLeg(l0);
	const HypothesisSet h = bb.compact();
	ASSERT_EQ(h.tables.size(), 1u);
	ASSERT_EQ(h.legs.size(), 1u);
	EXPECT_EQ(h.legs[0].parent, 0);
	EXPECT_EQ(h.legs[0].corner, 1);
	EXPECT_EQ(h.shapeletParent, std::vector<Id>{0});
}

// A copy of the board (a move's backup, the sampler's MAP candidate) shares the problem's
// shapelets; a later reset of either board leaves the other's shapelets as they were.
TEST(Blackboard, CopiesKeepTheirShapeletsAcrossAReset)
{
	ModelParams p;
	Blackboard a(p);
	a.reset({{0.5, 0.3, 0, 0.5, 0}, {-0.5, 0.3, 0, 0.5, 1}});
	Blackboard b = a;
	EXPECT_EQ(&a.shapelets(), &b.shapelets());  // shared, not copied
	a.reset({{2, 2, 1, 0.1, 0}});
	ASSERT_EQ(b.shapelets().size(), 2u);
	EXPECT_EQ(b.shapelets()[1].x, -0.5);
	ASSERT_EQ(a.shapelets().size(), 1u);
	EXPECT_EQ(a.shapelets()[0].x, 2);
	b = a;
	EXPECT_EQ(b.shapelets().size(), 1u);
	EXPECT_EQ(Blackboard(p).shapelets().size(), 0u);
}

// Legs' folded evidence starts empty in a reused slot after a reset, though reset keeps storage.
TEST(Blackboard, EvidenceOfAReusedSlotIsTheNewLegs)
{
	ModelParams p;
	Blackboard bb(p);
	bb.reset({{0.5, 0.3, 0, 0.5, 0}});
	LegEvidence e;
	e.add({0.52, 0.3, 0, 0.5, 0}, squareLeg(0.5, 0.3), p);
	for (int i = 0; i < 5; i++) bb.addLeg(squareLeg(i, 0), e);
	bb.reset({{0.5, 0.3, 0, 0.5, 0}});
	const Id l = bb.addLeg(squareLeg(0.5, 0.3));
	EXPECT_TRUE(bb.evidence(l).empty());
	const Id m = bb.addLeg(squareLeg(0.7, 0.3), e);
	EXPECT_EQ(bb.evidence(m).count(), 1u);
}

// The board keeps each wall's frame as the wall is added, moved, and its slot reused.
TEST(Blackboard, WallFramesFollowTheirWalls)
{
	const auto same = [](const Wall::Frame& a, const Wall::Frame& b) {
		bool eq = a.len == b.len && a.ux == b.ux && a.uy == b.uy;
		for (int k = 0; k < 4; k++) eq = eq && a.normal[k] == b.normal[k];
		return eq;
	};
	ModelParams p;
	Blackboard bb(p);
	bb.reset({{0.5, 0.3, 0, 0.5, 0}});
	const Wall a{0, 0, 2, 0, 0.1, 0.3}, b{1, 1, 1, 3, 0.1, 0.3}, c{-1, 0.5, 0.2, -0.4, 0.1, 0.3};
	const Id wa = bb.addWall(a), wb = bb.addWall(b);
	EXPECT_TRUE(same(bb.wallFrame(wa), a.frame()));
	EXPECT_TRUE(same(bb.wallFrame(wb), b.frame()));
	bb.setWall(wa, c);
	EXPECT_TRUE(same(bb.wallFrame(wa), c.frame()));
	EXPECT_FALSE(same(bb.wallFrame(wa), a.frame()));
	bb.removeWall(wb);
	EXPECT_EQ(bb.addWall(a), wb);  // the slot is reused, with the new wall's frame
	EXPECT_TRUE(same(bb.wallFrame(wb), a.frame()));
}
