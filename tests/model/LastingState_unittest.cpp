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

// With a gap (insertOpts leg_merge_gap: whisker-slam's particle maps), legs that come within
// it of each other are merged as overlapping ones are; legs further apart are left alone.
TEST(LastingState, LegsWithinTheGapAreMergedThoseBeyondItAreNot)
{
	const ModelParams p;
	Table t;
	t.leg_width = 0.05, t.texture = 0.7;
	// Legs 5 cm wide: 0 and 1 are 1.5 cm apart edge to edge, 2 is 4 cm beyond 1.
	const auto state = [&] {
		LastingState st(p);
		st.restore(
			{t}, {1.0}, {}, {leg(1, 1, NONE, -1), leg(1.065, 1, NONE, -1), leg(1.155, 1, 0, 0)}, {{}, {}, {}},
			{contact(0.97, 1, 0, 1), contact(0.975, 1.01, 0, 2), contact(1.09, 1, 1, 3), contact(1.18, 1, 2, 4)}, 5, p);
		return st;
	};
	for (const double gap : {0.0, 0.01})
	{
		LastingState st = state();
		std::vector<Id> kept, touched;
		EXPECT_EQ(st.mergeOverlappingLegs({0, 1, 2}, kept, touched, gap), 0u) << gap;
		EXPECT_EQ(st.legCount(), 3u) << gap;
	}
	LastingState st = state();
	std::vector<Id> kept, touched;
	EXPECT_EQ(st.mergeOverlappingLegs({1}, kept, touched, 0.02), 1u);
	EXPECT_TRUE(st.hasLeg(0));  // it explains more
	EXPECT_FALSE(st.hasLeg(1));
	EXPECT_EQ(st.contactsOf(0).size(), 3u);
	EXPECT_TRUE(st.hasLeg(2));  // 4 cm from the gone leg, 10.5 cm from the kept one
	EXPECT_TRUE(st.hasTable(0));
}

// A leg mapped again a few centimetres beside the first (doc/slam.md, "Legs mapped again beside
// the first") is counted, from either side, also across grid cells; legs further apart are not.
TEST(LastingState, LegsBesideAreThoseWithAnotherLegWithinTheDistance)
{
	const ModelParams p;
	LastingState st(p);
	const std::vector<Leg> legs{leg(1, 1, NONE, -1), leg(1.06, 1.03, NONE, -1), leg(-0.04, 2, NONE, -1),
								leg(0.04, 2, NONE, -1), leg(3, 3, NONE, -1)};
	st.restore({}, {}, {}, legs, std::vector<LegEvidence>(legs.size()), {}, 0, p);
	EXPECT_EQ(st.legsBeside(0.1), 4u);
	EXPECT_EQ(st.legsBeside(0.07), 2u);  // 0.067 apart: beside; 0.08 apart: not
	EXPECT_EQ(st.legsBeside(0.05), 0u);
	EXPECT_EQ(st.legsBeside(3), 5u);
}

namespace
{
/** 40 legs without table, 0.3 m apart along y = 0, each explaining one contact. */
LastingState rowOfLegs(const ModelParams& p)
{
	std::vector<Leg> legs;
	std::vector<LastingState::Contact> contacts;
	for (int i = 0; i < 40; i++)
	{
		legs.push_back(leg(0.3 * i, 0, NONE, -1));
		contacts.push_back(contact(0.3 * i + 0.025, 0, i, static_cast<uint64_t>(i)));
	}
	LastingState st(p);
	st.restore({}, {}, {}, legs, std::vector<LegEvidence>(legs.size()), contacts, 40, p);
	return st;
}

LastingState::Radii radii(double r) { return {r, r, r}; }
}  // namespace

// A resampled copy of the map shares its chunks until one of the copies writes (doc/map-plugin.md,
// "Copies"); a region written back as it was read writes nothing, so it unshares nothing.
TEST(LastingState, ARegionWrittenBackUnchangedUnsharesNothing)
{
	const ModelParams p;
	LastingState st = rowOfLegs(p);
	const LastingState copy = st;
	ASSERT_EQ(st.sharing().shared, st.sharing().chunks);
	LastingState::Region r(p);
	st.extract({20}, radii(1.0), p, r);
	ASSERT_GE(r.legs.size(), 5u);
	std::vector<Id> tables, legs;
	st.replace(r, r.board, {}, tables, legs);
	for (size_t i = 0; i < r.legs.size(); i++) EXPECT_EQ(legs[i], r.legs[i]);  // same store ids
	EXPECT_EQ(st.sharing().shared, st.sharing().chunks);
	EXPECT_EQ(copy.sharing().shared, copy.sharing().chunks);
	EXPECT_EQ(st.contactsOf(legs[0]).size(), 1u);
}

// A leg the solution moves keeps its store id, is found at its new place and no longer at the
// old one; a leg it removes leaves its contact unexplained; contacts it hands from one leg to
// another are listed in insertion order.
TEST(LastingState, ReplaceMovesRemovesAndRelinksLegsInPlace)
{
	const ModelParams p;
	LastingState st = rowOfLegs(p);
	LastingState::Region r(p);
	st.extract({20}, radii(0.7), p, r);  // legs 18..22 (x = 5.4 .. 6.6), contacts 18..22
	ASSERT_EQ(r.legs.size(), 5u);
	ASSERT_EQ(r.contacts.size(), 5u);
	Blackboard solved = r.board;
	Leg moved = solved.leg(2);  // leg 20, at x = 6.0
	moved.y = 0.8;  // into another cell of the leg grid
	solved.setLeg(2, moved);
	solved.setShapeletParent(1, 2);  // contact 19 (older) to leg 20
	solved.removeLeg(1);  // leg 19
	std::vector<Id> tables, legs;
	st.replace(r, solved, {}, tables, legs);
	EXPECT_EQ(legs[2], r.legs[2]);
	EXPECT_EQ(legs[1], NONE);
	EXPECT_FALSE(st.hasLeg(r.legs[1]));
	EXPECT_DOUBLE_EQ(st.leg(legs[2]).y, 0.8);
	EXPECT_EQ(st.contactsOf(legs[2]), (std::vector<Id>{r.contacts[1], r.contacts[2]}));
	EXPECT_EQ(st.contact(r.contacts[1]).leg, legs[2]);
	// The moved leg is found where it now stands, in a problem around a contact near it.
	const Id near = st.addContact([] {
		whiskermap::obs::Shapelet s;
		s.x = 6.0, s.y = 0.9;
		return s;
	}());
	LastingState::Region again(p);
	st.extract({near}, radii(0.15), p, again);
	EXPECT_EQ(again.legs, std::vector<Id>{legs[2]});
}
