#include <gtest/gtest.h>
#include <whiskermap/inference/BlackboardSampler.h>
#include <whiskermap/inference/SweptMemory.h>
#include <whiskermap/model/Posterior.h>

#include "SyntheticTable.h"

using namespace whiskermap;
using model::ModelParams;
using model::Table;

namespace
{
// Two legs of a table touched from one side (the paper's ambiguous poses): the table at y > 0
// and its mirror image across the touched legs explain them equally well.
ModelParams withFreeSpace(bool on)
{
	ModelParams p;
	p.free_space = on;
	return p;
}
const ModelParams P = withFreeSpace(true);
const Table TRUTH{0, 0.3, 0, P.leg_width, P.texture};  // corners 2, 3 at (-0.5, 0), (0.5, 0)
const Table MIRROR{0, -0.3, 0, P.leg_width, P.texture};  // same legs at its corners 1, 0

std::vector<obs::Shapelet> touchedFromBelow()
{
	// Face 3 (normal -y) of the legs at corners 2 and 3, two contacts each.
	return test::touchTable(TRUTH, P, {{2, 3, 0.0}, {2, 3, 0.01}, {3, 3, 0.0}, {3, 3, -0.01}});
}

// The robot below the legs: 0.6 m whiskers pivoting under each touched leg swept from behind
// (180 deg) round to 330 deg, through the mirror's far corners, never reaching the truth.
const std::vector<obs::SweptSector> SWEPT{{-0.5, -0.3, 0.6, M_PI, 5 * M_PI / 6}, {0.5, -0.3, 0.6, M_PI, 5 * M_PI / 6}};

// A board holding the shapelets, `table` with legs at every corner (linked to the contacts).
double logJointOf(const Table& table, const ModelParams& p, bool invented)
{
	model::Blackboard bb(p);
	bb.reset(touchedFromBelow(), SWEPT);
	const model::Id t = bb.addTable(table);
	for (int c = 0; c < 4; c++)
	{
		model::Leg l{0, 0, table.theta, p.leg_width, p.leg_width, p.texture, t, -1};
		model::tableCorner(table, c, p, l.x, l.y);
		const bool touched = std::abs(l.y) < 1e-9;
		if (!touched && !invented) continue;
		const model::Id id = bb.addLeg(l);
		for (size_t s = 0; s < bb.shapelets().size(); s++)
			if (touched && std::abs(bb.shapelets()[s].x - l.x) < 0.1) bb.setShapeletParent(s, id);
	}
	return model::logJoint(bb);
}
}  // namespace

// Without free space the table and its mirror tie; with it the mirror, whose far legs (or
// empty corners) stand in swept space, loses about log(1 / p_miss) per leg, the truth nothing.
TEST(FreeSpace, MirrorTableLosesOnAHandMadeBoard)
{
	const ModelParams off = withFreeSpace(false);
	for (const bool invented : {true, false})
	{
		EXPECT_NEAR(logJointOf(TRUTH, off, invented), logJointOf(MIRROR, off, invented), 1e-9);
		EXPECT_NEAR(logJointOf(TRUTH, P, invented), logJointOf(TRUTH, off, invented), 1e-12);
		EXPECT_NEAR(
			logJointOf(MIRROR, P, invented), logJointOf(MIRROR, off, invented) + 2 * std::log(P.free_space_p_miss), 1e-6);
	}
}

// The sampler, given the sweeps' free space, puts the table on the side nobody swept; without
// it, the same seeds give the mirror about as often as the truth (7 of 10 here). One seed of
// the ten finds no table either way (a search failure the free space does not cause).
TEST(FreeSpace, SamplerResolvesTheMirrorAmbiguity)
{
	inference::BlackboardSampler on(P, inference::SamplerParams()), off(withFreeSpace(false), inference::SamplerParams());
	const auto side = [](const inference::StepResult& r) {
		EXPECT_LE(r.map.tables.size(), 1u);
		return r.map.tables.empty() ? 0 : r.map.tables[0].y > 0 ? 1 : -1;  // truth +1, mirror -1
	};
	int truth = 0, mirror = 0, mirrorWithout = 0;
	for (uint64_t seed = 1; seed <= 10; seed++)
	{
		const int s = side(on.step(touchedFromBelow(), SWEPT, seed));
		truth += s == 1, mirror += s == -1;
		mirrorWithout += side(off.step(touchedFromBelow(), seed)) == -1;
	}
	EXPECT_EQ(mirror, 0);
	EXPECT_GE(truth, 9);
	EXPECT_GE(mirrorWithout, 3);  // the ambiguity is real without free space
}

// The free space of the sweeps whose shapelets are in the working memory, and of the newest.
TEST(FreeSpace, SweptMemoryFollowsTheWorkingMemory)
{
	const auto sector = [](double x) { return std::vector<obs::SweptSector>{{x, 0, 0.6, 0, 1}}; };
	const auto pivots = [](const inference::SweptMemory& m) {
		std::vector<double> x;
		for (const auto& s : m.sectors()) x.push_back(s.x);
		return x;
	};
	inference::SweptMemory m(3);  // three shapelets
	m.add(2, sector(1));
	EXPECT_EQ(pivots(m), (std::vector<double>{1}));
	m.add(0, sector(2));  // no contact: kept while it is the newest
	EXPECT_EQ(pivots(m), (std::vector<double>{1, 2}));
	m.add(2, sector(3));  // one of sweep 1's shapelets is still in memory; sweep 2 gave none
	EXPECT_EQ(pivots(m), (std::vector<double>{1, 3}));
	m.add(1, sector(4));  // sweep 1's shapelets have left
	EXPECT_EQ(pivots(m), (std::vector<double>{3, 4}));
	m.clear();
	EXPECT_TRUE(m.sectors().empty());
}
