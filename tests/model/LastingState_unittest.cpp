#include <gtest/gtest.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/LastingState.h>

#include <algorithm>

using namespace whiskermap::model;

namespace
{
Leg leg(double x, double y, Id parent, int corner)
{
	Leg l;
	l.x = x, l.y = y, l.wx = l.wy = 0.05, l.texture = 0.7, l.parent = parent, l.corner = corner;
	return l;
}

LastingState::Contact contact(double x, double y, Id legIndex, uint64_t seq)
{
	LastingState::Contact c;
	c.shapelet.x = x, c.shapelet.y = y, c.shapelet.texture = 0.7;
	c.leg = legIndex, c.seq = seq;
	return c;
}

/** Legs of `st` whose rectangles overlap another's. */
size_t overlapping(const LastingState& st)
{
	size_t n = 0;
	for (Id a = 0; a < st.legIdBound(); a++)
		for (Id b = 0; b < st.legIdBound(); b++)
			n += a != b && st.hasLeg(a) && st.hasLeg(b) && legRect(st.leg(a)).overlaps(legRect(st.leg(b)));
	return n;
}
}  // namespace

// The long-log defect (doc/reliability.md, "A million poses"): a leg born beside a leg holding
// thousands of contacts, at the same corner of the same table, took the contacts the big leg
// fitted worst and grew; later a second table stood on such legs. The stored map now keeps
// no two overlapping legs: the smaller is merged into the bigger.
TEST(LastingState, OverlappingLegsAreMergedIntoTheOneExplainingMore)
{
	const ModelParams p;
	Table t;
	t.leg_width = 0.05, t.texture = 0.7;
	LegEvidence heavy;
	const Leg big = leg(0.5, 0.3, 0, 0);
	for (int i = 0; i < 50; i++)
	{
		whiskermap::obs::Shapelet s;
		s.x = 0.525, s.y = 0.3 + 0.0005 * (i - 25), s.texture = 0.7;
		heavy.add(s, big, p);
	}
	LastingState st(p);
	st.restore(
		{t, t}, {1.0, 1.0}, {}, {big, leg(0.509, 0.305, 0, 0), leg(-0.5, 0.3, 0, 1), leg(2, 2, 1, 0)},
		{heavy, {}, {}, {}},
		{contact(0.52, 0.31, 0, 1), contact(0.53, 0.33, 1, 2), contact(0.535, 0.32, 1, 3), contact(-0.5, 0.33, 2, 4)}, 5, p);
	ASSERT_EQ(overlapping(st), 2u);  // legs 0 and 1, seen from both sides
	std::vector<Id> kept, touched;
	EXPECT_EQ(st.mergeOverlappingLegs({1, 2, 3}, kept, touched), 1u);
	EXPECT_EQ(overlapping(st), 0u);
	EXPECT_FALSE(st.hasLeg(1));
	ASSERT_EQ(kept, std::vector<Id>{0});
	EXPECT_EQ(touched, std::vector<Id>{0});
	EXPECT_EQ(st.contactsExplained(0), 50u + 3u);  // its own, folded and explicit, and the duplicate's
	EXPECT_EQ(st.contactsOf(0).size(), 3u);
	EXPECT_EQ(st.leg(0).x, 0.5);  // the bigger one stays where it was
	EXPECT_EQ(st.legsOf(0), (std::vector<Id>{0, 2}));
	EXPECT_EQ(st.contactsExplained(2), 1u);  // legs that overlap nothing are left alone
	EXPECT_TRUE(st.hasTable(1));
	EXPECT_EQ(st.mergeOverlappingLegs({0, 2, 3}, kept, touched), 0u);  // nothing left to merge
}

TEST(LastingState, ATableWhoseOnlyLegIsMergedAwayGoes)
{
	const ModelParams p;
	Table t;
	t.leg_width = 0.05, t.texture = 0.7;
	LastingState st(p);
	// Leg 1 (under table 1, alone) overlaps leg 0 (no table) and explains fewer contacts.
	st.restore(
		{t, t}, {1.0, 1.0}, {}, {leg(1, 1, NONE, -1), leg(1.02, 1.01, 1, 0), leg(3, 3, 0, 0)}, {{}, {}, {}},
		{contact(1.02, 1, 0, 1), contact(1.03, 1.02, 0, 2), contact(1.04, 1.02, 1, 3)}, 4, p);
	std::vector<Id> kept, touched;
	EXPECT_EQ(st.mergeOverlappingLegs({0}, kept, touched), 1u);
	EXPECT_FALSE(st.hasLeg(1));
	EXPECT_FALSE(st.hasTable(1));
	EXPECT_TRUE(st.hasTable(0));
	EXPECT_EQ(st.contactsOf(0).size(), 3u);
	EXPECT_EQ(st.leg(0).parent, NONE);
}
