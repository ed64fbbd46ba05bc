// The wall moves (doc/sampler.md, "Walls"): each move and its declared reverse give back the
// same board with opposite changes of logJoint and opposite log proposal ratios; the
// data-driven birth takes a line of wall contacts from the legs that held them.
#include <whiskermap/inference/TableProposals.h>
#include <whiskermap/inference/WallProposals.h>
#include <whiskermap/inference/moves/WallBirthDeath.h>
#include <whiskermap/inference/moves/WallLink.h>
#include <whiskermap/inference/moves/WallMerge.h>
#include <whiskermap/inference/moves/WallRefit.h>

#include "MoveBoards.h"

using namespace whiskermap;
using inference::moves::Proposal;
using model::Id;
using model::NONE;

namespace
{
model::ModelParams wallParams()
{
	model::ModelParams p;
	p.walls = true;
	return p;
}

/** A board of `n` contacts along face +1 of the wall y = -0.05 .. 0.05 (x from 0, every
 *  0.25 m), 2 mm of position noise and small normal errors, all unexplained. */
struct WallBoard
{
	explicit WallBoard(int n, uint64_t seed = 1) : b(seed, false, wallParams())
	{
		std::vector<obs::Shapelet> shapelets;
		for (int i = 0; i < n; i++)
		{
			obs::Shapelet s;
			s.x = 0.25 * i, s.y = 0.05 + 0.002 * ((i * 7 + static_cast<int>(seed)) % 3 - 1);
			s.normal = M_PI_2 + 0.02 * ((i + static_cast<int>(seed)) % 3 - 1);
			s.texture = 0.3;
			shapelets.push_back(s);
		}
		b.bb.reset(shapelets);
	}
	test::MoveBoard b;
};

/** Applies a proposal (keeps it) and checks logTarget against logJoint. */
template <class M, class Propose>
Proposal applied(test::MoveBoard& b, M& move, Propose&& propose)
{
	const double before = model::logJoint(b.bb);
	const std::optional<Proposal> p = propose();
	EXPECT_TRUE(p.has_value());
	if (!p) return {};
	move.finish(b.ctx, true);
	EXPECT_NEAR(model::logJoint(b.bb) - before, p->logTarget, 1e-7);
	return *p;
}

void expectSameWalls(const model::Blackboard& a, const model::Blackboard& b)
{
	ASSERT_EQ(a.wallCount(), b.wallCount());
	for (size_t s = 0; s < a.shapelets().size(); s++) EXPECT_EQ(a.explained(s), b.explained(s));
}
}  // namespace

TEST(WallMoves, ProposalFromOneContact)
{
	WallBoard w(6);
	const auto c = inference::proposeWall(w.b.bb, 2);
	ASSERT_TRUE(c.has_value());
	EXPECT_EQ(c->inliers.size(), 6u);
	EXPECT_NEAR(std::abs(c->wall.x1 - c->wall.x0), 1.25, 0.01);
	EXPECT_NEAR((c->wall.y0 + c->wall.y1) / 2, 0.0, 0.003);  // the centre line behind the face
	// Two contacts do not make a wall proposal; nor do contacts further apart than the gap.
	WallBoard two(2);
	EXPECT_FALSE(inference::proposeWall(two.b.bb, 0).has_value());
}

TEST(WallMoves, BirthThenDeath)
{
	WallBoard w(5);
	const model::Blackboard before = w.b.bb;
	inference::moves::WallBirthDeath move(w.b.P);
	const Proposal birth = applied(w.b, move, [&] { return move.birth(w.b.ctx, 1); });
	ASSERT_EQ(w.b.bb.wallCount(), 1u);
	EXPECT_GT(birth.logTarget, 0);  // five agreeing contacts: the wall beats their null cause
	const Id wall = w.b.bb.shapeletWall(0);
	ASSERT_NE(wall, NONE);
	const Proposal death = applied(w.b, move, [&] { return move.death(w.b.ctx, wall); });
	ASSERT_TRUE(std::isfinite(death.logReverse));
	ASSERT_TRUE(std::isfinite(birth.logReverse));
	test::expectReverses(birth, death, "wall birth, death");
	expectSameWalls(before, w.b.bb);
	test::expectSameBoard(before, w.b.bb, "wall birth, death");
}

TEST(WallMoves, DeathThenBirth)
{
	WallBoard w(5);
	inference::moves::WallBirthDeath move(w.b.P);
	applied(w.b, move, [&] { return move.birth(w.b.ctx, 0); });
	const model::Blackboard before = w.b.bb;
	const Id wall = w.b.bb.shapeletWall(0);
	const Proposal death = applied(w.b, move, [&] { return move.death(w.b.ctx, wall); });
	const Proposal birth = applied(w.b, move, [&] { return move.birth(w.b.ctx, 0); });
	test::expectReverses(death, birth, "wall death, birth");
	expectSameWalls(before, w.b.bb);
	EXPECT_NEAR(w.b.bb.wall(w.b.bb.shapeletWall(0)).x1, before.wall(wall).x1, 1e-12);
}

TEST(WallMoves, BirthTakesContactsFromLegs)
{
	// Each contact first explained by a free leg of its own (standing in the wall), then the
	// birth: the wall explains them, the legs go, and the joint rises.
	WallBoard w(5);
	model::Blackboard& bb = w.b.bb;
	for (size_t s = 0; s < bb.shapelets().size(); s++) bb.setShapeletParent(s, bb.addLeg(w.b.ctx.newLegFor(s)));
	inference::moves::WallBirthDeath move(w.b.P);
	const Proposal birth = applied(w.b, move, [&] { return move.birth(w.b.ctx, 2); });
	EXPECT_GT(birth.logTarget, 0);
	EXPECT_EQ(bb.legCount(), 0u);
	EXPECT_EQ(bb.shapeletsOfWall(bb.shapeletWall(0)).size(), 5u);
	EXPECT_FALSE(std::isfinite(birth.logReverse));  // the death leaves them to no cause, not to legs
}

// The birth and the death score their change from local pieces (inliers unlinked, free legs
// removed, logOddsWall): the same as the whole joint's change on a board where the wall's
// contacts are held by free legs, by a table's leg (which stays, standing in the new wall,
// with its table), and where a leg the birth does not touch stands in the wall too.
TEST(WallMoves, BirthAndDeathChangesMatchTheJointOnAMixedBoard)
{
	WallBoard w(6);
	model::Blackboard& bb = w.b.bb;
	// A contact on the wall's line facing the other way: not an inlier; its leg stays.
	std::vector<obs::Shapelet> shapelets(bb.shapelets().begin(), bb.shapelets().end());
	obs::Shapelet odd = shapelets[3];
	odd.x += 0.12, odd.normal = -M_PI_2;
	shapelets.push_back(odd);
	bb.reset(shapelets);
	for (const size_t s : {0, 1, 6}) bb.setShapeletParent(s, bb.addLeg(w.b.ctx.newLegFor(s)));
	const Id tableLeg = bb.addLeg(w.b.ctx.newLegFor(2));
	bb.setShapeletParent(2, tableLeg);
	bb.setLegParent(tableLeg, bb.addTable(inference::tableWithLegAt(w.b.P, bb.leg(tableLeg), 0, 0, 0)));
	inference::moves::WallBirthDeath move(w.b.P);
	const size_t legs = bb.legCount();
	applied(w.b, move, [&] { return move.birth(w.b.ctx, 4); });
	ASSERT_EQ(bb.wallCount(), 1u);
	EXPECT_EQ(bb.legCount(), legs - 2);  // the two free legs went, the table's and the odd one stay
	EXPECT_TRUE(bb.hasLeg(tableLeg));
	EXPECT_NE(bb.shapeletParent(6), NONE);
	applied(w.b, move, [&] { return move.death(w.b.ctx, bb.shapeletWall(0)); });
	EXPECT_EQ(bb.wallCount(), 0u);
}

TEST(WallMoves, ReleaseThenLink)
{
	for (uint64_t seed = 1; seed <= 5; seed++)
	{
		WallBoard w(5, seed);
		inference::moves::WallBirthDeath births(w.b.P);
		applied(w.b, births, [&] { return births.birth(w.b.ctx, 0); });
		const Id wall = w.b.bb.shapeletWall(0);
		const model::Blackboard before = w.b.bb;
		inference::moves::WallLink move;
		const Proposal release = applied(w.b, move, [&] { return move.release(w.b.ctx, wall); });
		EXPECT_LT(release.logTarget, 0);
		const Proposal link = applied(w.b, move, [&] { return move.link(w.b.ctx, wall); });
		test::expectReverses(release, link, "release, link");
		EXPECT_NEAR(release.logForward, -std::log(5.0), 1e-12);
		EXPECT_NEAR(link.logReverse, -std::log(5.0), 1e-12);
		expectSameWalls(before, w.b.bb);
		EXPECT_EQ(w.b.bb.shapeletsOfWall(wall), before.shapeletsOfWall(wall));
	}
}

TEST(WallMoves, RefitImprovesAndIsIdempotent)
{
	WallBoard w(6);
	inference::moves::WallBirthDeath births(w.b.P);
	applied(w.b, births, [&] { return births.birth(w.b.ctx, 0); });
	const Id wall = w.b.bb.shapeletWall(0);
	model::Wall off = w.b.bb.wall(wall);
	off.y0 += 0.004, off.y1 -= 0.003, off.x1 += 0.2;
	w.b.bb.setWall(wall, off);
	inference::moves::WallRefit move;
	const Proposal refit = applied(w.b, move, [&] { return move.propose(w.b.ctx, wall); });
	EXPECT_GT(refit.logTarget, 0);
	EXPECT_FALSE(std::isfinite(refit.logReverse));
	const Proposal again = applied(w.b, move, [&] { return move.propose(w.b.ctx, wall); });
	EXPECT_NEAR(again.logTarget, 0, 1e-9);
	EXPECT_EQ(again.logReverse, 0);
}

TEST(WallMoves, LegStandingInAWallPaysTheOverlapFactor)
{
	WallBoard w(5);
	inference::moves::WallBirthDeath births(w.b.P);
	applied(w.b, births, [&] { return births.birth(w.b.ctx, 0); });
	model::Blackboard& bb = w.b.bb;
	model::Leg inside;
	inside.x = 0.5, inside.y = 0.0, inside.wx = inside.wy = 0.05, inside.texture = 0.3;
	model::Leg outside = inside;
	outside.y = 0.3;
	const Id a = bb.addLeg(inside), b = bb.addLeg(outside);
	EXPECT_NEAR(model::logOddsLeg(bb, a) - model::logOddsLeg(bb, b), std::log(w.b.P.epsilon), 1e-9);  // eq. 16
}

TEST(WallMoves, MergeJoinsTwoPiecesOfOneWall)
{
	// Two walls along one line, each explaining half of 8 contacts: the merge leaves one wall
	// with all of them, saves a wall's prior and is judged on the change of logJoint.
	WallBoard w(8);
	model::Blackboard& bb = w.b.bb;
	const auto first = inference::proposeWall(bb, 0, 3);
	ASSERT_TRUE(first.has_value());
	model::Wall left = first->wall, right = first->wall;
	left.x1 = 0.75, right.x0 = 1.0;  // the contacts at 0 .. 0.75 and 1.0 .. 1.75
	const Id a = bb.addWall(left), b = bb.addWall(right);
	for (size_t s = 0; s < 8; s++) bb.setShapeletWall(s, s < 4 ? a : b);
	std::vector<Id> others;
	inference::moves::WallMerge::candidates(bb, a, others);
	ASSERT_EQ(others, std::vector<Id>{b});
	inference::moves::WallMerge move(w.b.P);
	const Proposal p = applied(w.b, move, [&] { return move.merge(w.b.ctx, a, b); });
	EXPECT_GT(p.logTarget, 10);
	EXPECT_FALSE(std::isfinite(p.logReverse));
	ASSERT_EQ(bb.wallCount(), 1u);
	EXPECT_EQ(bb.shapeletsOfWall(bb.shapeletWall(0)).size(), 8u);
	EXPECT_NEAR(bb.wall(bb.shapeletWall(0)).length(), 1.75, 0.01);
	// A wall 20 cm off the line, or 1 m further along, is not a candidate.
	model::Wall off = right, far = right;
	off.y0 += 0.2, off.y1 += 0.2, far.x0 += 1.5, far.x1 += 1.5;
	bb.addWall(off), bb.addWall(far);
	inference::moves::WallMerge::candidates(bb, bb.shapeletWall(0), others);
	EXPECT_TRUE(others.empty());
}

TEST(WallMoves, MergedEvidenceScoresAllTheContacts)
{
	// Contacts of one wall folded in two lots (each with its own anchor and reference face,
	// the second from the far face) and merged score as if folded into one.
	const model::ModelParams p = wallParams();
	const model::Wall wall{0, 0, 3, 0.1, 0.1, 0.3};
	model::WallEvidence one, a, b;
	for (int i = 0; i < 12; i++)
	{
		obs::Shapelet s;
		const int side = i % 4 == 3 ? -1 : 1;
		const model::Wall::FaceHit h = wall.face(0.25 * i, 0, side);
		s.x = 0.25 * i, s.y = 0.1 * 0.25 * i / 3 + side * 0.05 + 0.002 * (i % 3 - 1);
		s.normal = h.normal + 0.03 * (i % 2 ? 1 : -1), s.texture = 0.25 + 0.01 * i;
		one.add(s, wall, p);
		(i < 6 && side > 0 ? a : b).add(s, wall, p);
	}
	const model::WallEvidence merged = inference::moves::mergeEvidence(a, b);
	EXPECT_EQ(merged.count(), one.count());
	for (const model::Wall& at : {wall, model::Wall{-0.1, 0.02, 3.2, 0.08, 0.1, 0.35}, model::Wall{3, 0.1, 0, 0, 0.1, 0.3}})
		EXPECT_NEAR(merged.logLikelihood(at, p), one.logLikelihood(at, p), 1e-6);
	const model::Wall f = merged.fit(0.1), g = one.fit(0.1);
	EXPECT_TRUE(f.sameAs(g, 1e-6));
}
