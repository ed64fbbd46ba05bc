#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/model/Posterior.h>

#include "SyntheticTable.h"

using namespace whiskermap;
using inference::BlackboardSampler;
using inference::SamplerParams;
using model::Blackboard;
using model::Id;
using model::Leg;
using model::LegEvidence;
using model::ModelParams;
using model::NONE;
using model::Table;
using test::touchTable;

namespace
{
const ModelParams P;
const Table truth{1.3, -0.4, 0.5, P.leg_width, P.texture};

Leg legAt(const Table& t, int corner, Id parent)
{
	Leg l{0, 0, t.theta, P.leg_width, P.leg_width, t.texture, parent, -1};
	model::tableCorner(t, corner, P, l.x, l.y);
	return l;
}

/** Evidence of contacts along faces of the true leg at `corner`. */
LegEvidence foldedOn(int corner, const std::vector<int>& faces, const Leg& at)
{
	LegEvidence e;
	std::vector<test::Touch> touches;
	for (const int f : faces)
		for (const double a : {-0.01, 0.0, 0.012}) touches.push_back({corner, f, a});
	for (const auto& s : touchTable(truth, P, touches)) e.add(s, at, P);
	return e;
}
}  // namespace

// Two legs standing on one real leg, each holding folded contacts of a different face of it
// (as when the lasting map placed a second leg before it knew the first): the local anneal
// merges them into one leg that holds all the contacts.
TEST(LocalAnneal, MergesTwoLegsOnOneRealLeg)
{
	for (const double turn : {0.0, M_PI_2, M_PI})
	{
		Blackboard bb(P);
		const auto fresh = touchTable(truth, P, {{0, 0, 0.005}});
		bb.reset(fresh);
		const Id t = bb.addTable(truth);
		for (int c = 1; c < 4; c++) bb.addLeg(legAt(truth, c, t), foldedOn(c, {c}, legAt(truth, c, t)));
		Leg a = legAt(truth, 0, t), b = legAt(truth, 0, t);
		a.x += 0.012, b.x -= 0.012, b.theta += turn;
		bb.addLeg(a, foldedOn(0, {0, 3}, a));
		bb.addLeg(b, foldedOn(0, {1}, b));
		BlackboardSampler sampler(P, SamplerParams{});
		sampler.anneal(bb, 3);
		const Blackboard& best = sampler.best();
		EXPECT_EQ(best.tableCount(), 1u) << "turn " << turn;
		EXPECT_EQ(best.legCount(), 4u) << "turn " << turn;
		uint32_t folded = 0;
		for (Id l = 0; l < best.legIdBound(); l++)
			if (best.hasLeg(l)) folded += best.evidence(l).count();
		EXPECT_EQ(folded, 3u * 3 + 6 + 3) << "no folded contact may be lost";
	}
}
