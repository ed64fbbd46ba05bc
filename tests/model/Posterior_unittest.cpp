#include <gtest/gtest.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <random>

using namespace whiskermap::model;

namespace
{
// Random blackboards dense enough that every factor fires: tables overlapping, legs near
// corners (some sharing one), overlapping legs, orphans, shapelets near legs.
struct RandomBoards
{
	ModelParams p;
	std::mt19937_64 rng{12345};

	RandomBoards()
	{
		p.epsilon = 0.05;
		p.free_space = true;  // scored wherever a board has swept sectors (eq. 21)
	}
	double u(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
	int pick(int n) { return static_cast<int>(rng() % static_cast<uint64_t>(n)); }

	/** With `lasting`: some legs carry folded contacts and fixed context objects stand around
	 *  (the lasting map's local problems). */
	Blackboard make(bool lasting = false)
	{
		std::vector<whiskermap::obs::Shapelet> shapelets;
		Blackboard bb(p);
		std::vector<Id> tables, legs;
		const int nt = 1 + pick(3);
		for (int i = 0; i < nt; i++)
			tables.push_back(bb.addTable({u(-0.4, 0.4), u(-0.4, 0.4), u(-M_PI, M_PI), p.leg_width, p.texture}));
		const int nl = 2 + pick(8);
		for (int i = 0; i < nl; i++)
		{
			Leg l{0, 0, u(-M_PI, M_PI), p.leg_width + u(-0.01, 0.01), p.leg_width, u(0.3, 0.7), NONE, -1};
			if (pick(4) > 0)
			{
				l.parent = tables[pick(nt)];
				tableCorner(bb.table(l.parent), pick(4), p, l.x, l.y);
				l.x += u(-0.03, 0.03);
				l.y += u(-0.03, 0.03);
			}
			else
			{
				l.x = u(-0.8, 0.8);
				l.y = u(-0.8, 0.8);
			}
			legs.push_back(bb.addLeg(l));
		}
		for (int i = 0; i < 7; i++)
		{
			const Leg& l = bb.leg(legs[pick(nl)]);
			shapelets.push_back({l.x + u(-0.05, 0.05), l.y + u(-0.05, 0.05), u(-M_PI, M_PI), u(0, 1), i});
		}
		// Two boards in three hold whisker sweeps' free space, with legs and corners in it.
		std::vector<whiskermap::obs::SweptSector> swept;
		for (int k = 0; pick(3) > 0 && k < 4; k++)
			swept.push_back({u(-0.8, 0.8), u(-0.8, 0.8), u(0.2, 0.7), u(-M_PI, M_PI), u(0.3, 2.5)});
		Blackboard withShapelets(p);
		withShapelets.reset(shapelets, swept);
		// Re-create the hypotheses on the board holding the shapelets (same ids).
		for (Id t : tables) withShapelets.addTable(bb.table(t));
		for (Id l : legs)
		{
			LegEvidence e;
			const Leg& leg = bb.leg(l);
			for (int k = 0; lasting && k < pick(4); k++)
				e.add({leg.x + u(-0.04, 0.04), leg.y + u(-0.04, 0.04), u(-M_PI, M_PI), u(0, 1), k}, leg, p);
			withShapelets.addLeg(leg, e);
		}
		for (size_t s = 0; s < shapelets.size(); s++)
			if (pick(5) > 0) withShapelets.setShapeletParent(s, legs[pick(nl)]);
		for (int k = 0; lasting && k < 3; k++)
		{
			withShapelets.addContextTable({u(-0.8, 0.8), u(-0.8, 0.8), u(-M_PI, M_PI), p.leg_width, p.texture});
			withShapelets.addContextLeg({u(-0.8, 0.8), u(-0.8, 0.8), u(-M_PI, M_PI), p.leg_width, p.leg_width, 0.5, NONE, -1});
		}
		return withShapelets;
	}
};
}  // namespace

namespace
{
/** Overlapping same-type pairs by brute force, context included (eq. 16): the reference
 *  for logJoint's hashed count. */
int bruteForceOverlaps(const Blackboard& bb)
{
	const ModelParams& p = bb.params();
	int n = 0;
	for (Id t = 0; t < bb.tableIdBound(); t++)
	{
		for (Id o = t + 1; o < bb.tableIdBound(); o++)
			n += bb.hasTable(o) && tableRect(bb.table(t), p).overlaps(tableRect(bb.table(o), p));
		for (const Table& c : bb.contextTables()) n += tableRect(bb.table(t), p).overlaps(tableRect(c, p));
	}
	for (Id l = 0; l < bb.legIdBound(); l++)
	{
		for (Id o = l + 1; o < bb.legIdBound(); o++)
			n += bb.hasLeg(o) && legRect(bb.leg(l)).overlaps(legRect(bb.leg(o)));
		for (const Leg& c : bb.contextLegs()) n += legRect(bb.leg(l)).overlaps(legRect(c));
	}
	return n;
}
}  // namespace

/** The same board under other parameters (ids kept: the generator never removes). */
Blackboard withParams(const Blackboard& bb, const ModelParams& p)
{
	Blackboard out(p);
	out.reset(bb.shapelets(), bb.swept().sectors());
	for (Id t = 0; t < bb.tableIdBound(); t++) out.addTable(bb.table(t));
	for (Id l = 0; l < bb.legIdBound(); l++) out.addLeg(bb.leg(l), bb.evidence(l));
	for (size_t s = 0; s < bb.shapelets().size(); s++) out.setShapeletParent(s, bb.shapeletParent(s));
	for (const Table& t : bb.contextTables()) out.addContextTable(t);
	for (const Leg& l : bb.contextLegs()) out.addContextLeg(l);
	return out;
}

// logJoint's overlap factor, counted through the spatial hashes, equals the brute-force count
// over all pairs: logJoint under two values of epsilon differs by the tables' phi_a, phi_b
// (eqs. 15, 17) and n log(eps1 / eps2), n the overlapping pairs (eq. 16).
TEST(Posterior, HashedOverlapsEqualBruteForce)
{
	RandomBoards gen;
	int overlapping = 0;
	for (int trial = 0; trial < 300; trial++)
	{
		const Blackboard bb = gen.make(trial % 2 == 1);
		ModelParams p2 = gen.p;
		p2.epsilon = 0.3;
		const Blackboard other = withParams(bb, p2);
		double constraints = 0;
		for (Id t = 0; t < bb.tableIdBound(); t++)
			constraints += logTableConstraints(bb.cornerCounts(t), gen.p) - logTableConstraints(bb.cornerCounts(t), p2);
		const double hashed = (logJoint(bb) - logJoint(other) - constraints) / std::log(gen.p.epsilon / p2.epsilon);
		const int n = bruteForceOverlaps(bb);
		EXPECT_NEAR(hashed, n, 1e-6) << "trial " << trial;
		overlapping += n > 0;
	}
	EXPECT_GT(overlapping, 100);
}

// For every present table and leg H of 300 random blackboards (half of them lasting-map
// problems: folded evidence on legs, context objects around; two in three with swept free
// space, eq. 21, on legs and empty corners): the local eq. 20 log-odds
// equals logJoint(B) - logJoint(B minus H, H's children unlinked).
TEST(Posterior, LocalLogOddsEqualsJointDifference)
{
	RandomBoards gen;
	int checked = 0, withTableOverlap = 0, withLegOverlap = 0, withSameCorner = 0, withEvidence = 0;
	int legsInFreeSpace = 0, cornersInFreeSpace = 0;
	for (int trial = 0; trial < 300; trial++)
	{
		const Blackboard bb = gen.make(trial % 2 == 1);
		const double full = logJoint(bb);
		for (Id t = 0; t < bb.tableIdBound(); t++)
		{
			Blackboard without = bb;
			without.removeTable(t);
			EXPECT_NEAR(logOddsTable(bb, t), full - logJoint(without), 1e-8);
			for (Id o = 0; o < bb.tableIdBound(); o++)
				withTableOverlap += o != t && tableRect(bb.table(t), gen.p).overlaps(tableRect(bb.table(o), gen.p));
			for (int k : bb.cornerCounts(t)) withSameCorner += k > 1;
			cornersInFreeSpace += bb.swept().logEmptyCorners(bb.table(t), bb.cornerCounts(t), gen.p) < -0.1;
			checked++;
		}
		for (Id l = 0; l < bb.legIdBound(); l++)
		{
			Blackboard without = bb;
			without.removeLeg(l);
			EXPECT_NEAR(logOddsLeg(bb, l), full - logJoint(without), 1e-8);
			withEvidence += !bb.evidence(l).empty();
			legsInFreeSpace += bb.swept().logFactor(legRect(bb.leg(l)), gen.p) < -0.1;
			for (Id o = 0; o < bb.legIdBound(); o++)
				withLegOverlap += o != l && legRect(bb.leg(l)).overlaps(legRect(bb.leg(o)));
			checked++;
		}
	}
	// The comparison only means something if the boards exercised every factor.
	EXPECT_GT(checked, 1000);
	EXPECT_GT(withTableOverlap, 50);
	EXPECT_GT(withLegOverlap, 20);
	EXPECT_GT(withSameCorner, 20);
	EXPECT_GT(withEvidence, 100);
	EXPECT_GT(legsInFreeSpace, 100);  // eq. 21 on legs
	EXPECT_GT(cornersInFreeSpace, 50);  // eq. 21 on the empty corners of tables
}

// Link gains (used by the sampler's reparent moves) equal joint differences too, for the
// current parent and for any other table.
TEST(Posterior, LinkGainsEqualJointDifference)
{
	RandomBoards gen;
	for (int trial = 0; trial < 200; trial++)
	{
		Blackboard bb = gen.make();
		for (Id l = 0; l < bb.legIdBound(); l++)
			for (Id t = 0; t < bb.tableIdBound(); t++)
			{
				Blackboard unlinked = bb, linked = bb;
				unlinked.setLegParent(l, NONE);
				linked.setLegParent(l, t);
				EXPECT_NEAR(logLegLinkGain(bb, l, t), logJoint(linked) - logJoint(unlinked), 1e-8);
			}
		for (size_t s = 0; s < bb.shapelets().size(); s++)
			for (Id l = 0; l < bb.legIdBound(); l++)
			{
				Blackboard unlinked = bb, linked = bb;
				unlinked.setShapeletParent(s, NONE);
				linked.setShapeletParent(s, l);
				EXPECT_NEAR(logShapeletLinkGain(bb, s, l), logJoint(linked) - logJoint(unlinked), 1e-8);
			}
	}
}

// logJoint by hand for a small board: one table, one leg at a corner, one shapelet on it.
TEST(Posterior, LogJointByHand)
{
	ModelParams p;
	Blackboard bb(p);
	whiskermap::obs::Shapelet s{0, 0, 0, p.texture, 0};
	const Table t{0, 0, 0, p.leg_width, p.texture};
	Leg l{0, 0, 0, p.leg_width, p.leg_width, p.texture, 0, -1};
	tableCorner(t, 0, p, l.x, l.y);
	s.x = l.x + p.leg_width / 2;  // on the leg's +x face, normal 0
	s.y = l.y;
	bb.reset({s});
	bb.addTable(t);
	bb.addLeg(l);
	bb.setShapeletParent(0, 0);
	const double cell = 3 * std::log(2 * p.delta), le = std::log(p.epsilon);
	const double expected = cell + std::log(p.c_T) + 3 * le  // table, 3 corners missing
							+ cell + std::log(p.alpha_L + p.c_L)  // leg exactly at its corner
							+ std::log(p.alpha_S + p.c_S);  // shapelet exactly on its face
	EXPECT_NEAR(logJoint(bb), expected, 1e-9);
	EXPECT_EQ(bb.leg(0).corner, 0);
}

TEST(Posterior, AnnealedAcceptance)
{
	EXPECT_NEAR(annealedAcceptance(0, 3), 0.5, 1e-12);
	EXPECT_NEAR(annealedAcceptance(std::log(3.0), 1), 0.75, 1e-12);  // odds 3:1
	EXPECT_NEAR(annealedAcceptance(std::log(3.0), 2), 0.9, 1e-12);  // odds 9:1
	EXPECT_EQ(annealedAcceptance(-1e6, 1), 0);
	EXPECT_EQ(annealedAcceptance(1e6, 1), 1);
}

// Moving a table and its legs changes logJoint exactly by the change of logJointAround (what
// the sampler's table refit is judged on), lasting-map boards included.
TEST(Posterior, LogJointAroundTracksTableMoves)
{
	RandomBoards gen;
	int moved = 0;
	for (int trial = 0; trial < 200; trial++)
	{
		Blackboard bb = gen.make(trial % 2 == 1);
		for (Id t = 0; t < bb.tableIdBound(); t++)
		{
			const double joint = logJoint(bb), around = logJointAround(bb, t);
			Table m = bb.table(t);
			m.x += gen.u(-0.05, 0.05), m.theta += gen.u(-0.2, 0.2);
			bb.setTable(t, m);
			for (const Id l : bb.legsOf(t))
			{
				Leg g = bb.leg(l);
				g.x += gen.u(-0.03, 0.03), g.y += gen.u(-0.03, 0.03);
				bb.setLeg(l, g);
			}
			EXPECT_NEAR(logJoint(bb) - joint, logJointAround(bb, t) - around, 1e-8) << "trial " << trial;
			moved += !bb.legsOf(t).empty();
		}
	}
	EXPECT_GT(moved, 150);
}
