#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/world/Table.h>

#include <Eigen/Geometry>
#include <random>

using namespace whiskermap;
using smooth::PathSmoother;

namespace
{
/** A robot driving 2 m along +x in 5 cm steps, 0.3 m from a wall along y = 0.3 + 0.05 (its
 *  face at y = 0.3) and towards an end wall whose face is at x = 2.4; odometry that reads every
 *  step 5% long. Each sweep touches the side wall straight to the left and the end wall straight
 *  ahead, with exact readings. */
struct Corridor
{
	std::vector<Eigen::Vector3d> truth, odometry;
	PathSmoother::TInput in;

	Corridor()
	{
		const size_t n = 41;
		const Eigen::Matrix3d cov = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();  // 1 cm, 0.57 degree a step
		for (size_t i = 0; i < n; i++)
		{
			truth.emplace_back(0.05 * static_cast<double>(i), 0, 0);
			odometry.emplace_back(0.0525 * static_cast<double>(i), 0, 0);
			in.increments.emplace_back(i ? 0.0525 : 0, 0, 0);
			in.covariances.push_back(cov);
			baseline::Contact side, ahead;
			side.p = {0, 0.3}, side.normal = -M_PI / 2, side.shaft = {0, 1}, side.sigma_r = 0.002;
			ahead.p = {2.4 - truth.back()[0], 0}, ahead.normal = M_PI, ahead.shaft = {1, 0}, ahead.sigma_r = 0.002;
			side.sweep = ahead.sweep = static_cast<uint32_t>(i);
			in.contacts.push_back(side), in.contacts.push_back(ahead);
		}
		in.path = odometry;  // the estimate to start from: dead reckoning
		in.solids = {
			world::Obstacle::rectangle({1.2, 0.35}, 0, 1.5, 0.05, 0.5),  // side wall, face y = 0.3
			world::Obstacle::rectangle({2.45 + 0.1, 0}, M_PI / 2, 1, 0.05, 0.5)};  // end wall as mapped: 10 cm off
	}

	/** The end wall replaced by two tables' legs 2: table 0's at (2.425, 0) (face x = 2.4),
	 *  table 1's `shift` from it (solids 3 and 7). */
	void endLegs(const Eigen::Vector2d& shift)
	{
		in.solids.pop_back();
		world::Table t;
		t.x = 2.925, t.y = 0.3, t.length = 1, t.width = 0.6, t.leg_width = 0.05;
		for (int k = 0; k < 4; k++) in.solids.push_back(t.leg(k, 0));
		t.x += shift.x(), t.y += shift.y();
		for (int k = 0; k < 4; k++) in.solids.push_back(t.leg(k, 1));
	}

	/** Exact increments, each with `covariance`, but a blind step to sweep 21 (1 m std-dev: the
	 *  robot was lifted), across which the start estimate drifted 3 cm along x. */
	void blindStep(Eigen::Matrix3d covariance)
	{
		for (size_t i = 1; i < truth.size(); i++) in.increments[i] = {0.05, 0, 0}, in.covariances[i] = covariance;
		in.covariances[21] = Eigen::Matrix3d::Identity();
		for (size_t i = 0; i < truth.size(); i++) in.path[i] = truth[i] + Eigen::Vector3d(i > 20 ? 0.03 : 0, 0, 0);
	}

	/** Every contact tied, the path the truth within 1 mm, `held` pairs held and `apart` left
	 *  apart, and the solids `unmoved` (indices) not shifted by more than 1 mm. */
	void expectDecided(
		const PathSmoother::TResult& r, size_t held, size_t apart, std::initializer_list<size_t> unmoved) const
	{
		EXPECT_EQ(r.duplicates, held);
		EXPECT_EQ(r.duplicatesApart, apart);
		EXPECT_EQ(r.tied, in.contacts.size());
		EXPECT_LT(worst(r.path, truth), 0.001);
		for (const size_t k : unmoved) EXPECT_LT(r.shifts[r.groupOf[k]].norm(), 0.001) << "solid " << k;
	}

	static double worst(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
	{
		double w = 0;
		for (size_t i = 0; i < a.size(); i++) w = std::max(w, (a[i].head<2>() - b[i].head<2>()).norm());
		return w;
	}
};
}  // namespace

TEST(PathSmoother, ContactsOnMappedSolidsCorrectABiasedOdometry)
{
	Corridor c;
	smooth::TSmoothParams p;
	p.gate = 0.15;  // the end wall is mapped 10 cm off and the odometry drifts 10 cm
	const auto r = PathSmoother::run(c.in, p);
	ASSERT_EQ(r.path.size(), c.truth.size());
	EXPECT_EQ(r.tied, c.in.contacts.size());
	EXPECT_NEAR(Corridor::worst(c.odometry, c.truth), 0.1, 1e-9);
	// The distances to the end wall fix every step; the start is known; the wall moves to fit.
	EXPECT_LT(Corridor::worst(r.path, c.truth), 0.002);
	EXPECT_EQ(r.path[0], c.in.path[0]);  // the known start is not moved
	ASSERT_EQ(r.shifts.size(), 2u);
	EXPECT_NEAR(r.shifts[1].x(), -0.1, 0.002);
	EXPECT_LT(r.costAfter, r.costBefore / 100);
	EXPECT_GT(r.iterations, 0u);
}

TEST(PathSmoother, WithoutTiesItFollowsTheOdometry)
{
	// No solid near any contact: only the odometry speaks, and the most probable path is the
	// odometry's, whatever path the smoother starts from (a filter's random walk, here).
	Corridor c;
	c.in.solids.clear();
	std::mt19937 rng(3);
	std::normal_distribution<double> step(0, 0.01);
	for (size_t i = 1; i < c.in.path.size(); i++)
		c.in.path[i] = c.in.path[i - 1] + Eigen::Vector3d(0.0525 + step(rng), step(rng), step(rng) / 5);
	ASSERT_GT(Corridor::worst(c.in.path, c.odometry), 0.02);
	const auto r = PathSmoother::run(c.in, smooth::TSmoothParams());
	EXPECT_EQ(r.tied, 0u);
	EXPECT_LT(Corridor::worst(r.path, c.odometry), 1e-6);
}

TEST(PathSmoother, AContactNearNoMappedFaceIsLeftOut)
{
	// Every tenth sweep also touches something unmapped 30 cm before the end wall: beyond the
	// gate of every face, so it ties to nothing and moves nothing.
	Corridor c;
	const size_t n = c.in.contacts.size();
	for (size_t i = 1; i < n; i += 20)
	{
		auto stray = c.in.contacts[i];
		stray.p.x() -= 0.3;
		c.in.contacts.push_back(stray);
	}
	smooth::TSmoothParams p;
	p.gate = 0.15;
	const auto r = PathSmoother::run(c.in, p);
	EXPECT_EQ(r.tied, n);
	EXPECT_LT(Corridor::worst(r.path, c.truth), 0.002);
}

TEST(PathSmoother, RejectsInconsistentInput)
{
	Corridor c;
	c.in.covariances.pop_back();
	EXPECT_THROW(PathSmoother::run(c.in, smooth::TSmoothParams()), core::Error);
	Corridor d;
	d.in.contacts[3].sweep = 41;
	EXPECT_THROW(PathSmoother::run(d.in, smooth::TSmoothParams()), core::Error);
	Corridor e;
	e.in.path.clear(), e.in.increments.clear(), e.in.covariances.clear(), e.in.contacts.clear();
	EXPECT_THROW(PathSmoother::run(e.in, smooth::TSmoothParams()), core::Error);
}

TEST(PathSmoother, ALegMappedTwiceIsHeldToOnePlace)
{
	// The corridor with exact odometry, but a blind step in the middle (1 m std-dev: the
	// robot was lifted), and the end wall replaced by a table leg whose face is at x = 2.4.
	// The particle drifted 3 cm along x across the blind step and mapped the leg a second
	// time, 3 cm further (a second table). Left alone, the copy's shift and the second half
	// of the path share the 3 cm; held to the first copy (eq. S4), the path is the truth.
	Corridor c;
	c.blindStep(c.in.covariances[1]);
	c.endLegs({0.03, 0});
	smooth::TSmoothParams p;
	const auto held = PathSmoother::run(c.in, p);
	EXPECT_EQ(held.duplicates, 1u);
	EXPECT_EQ(held.duplicatesApart, 0u);
	EXPECT_EQ(held.tied, c.in.contacts.size());
	EXPECT_LT(Corridor::worst(held.path, c.truth), 0.001);
	const Eigen::Vector2d a = c.in.solids[3].corners[0] + held.shifts[held.groupOf[3]];
	const Eigen::Vector2d b = c.in.solids[7].corners[0] + held.shifts[held.groupOf[7]];
	EXPECT_LT((a - b).norm(), 0.001);
	p.duplicate_sigma = 0;
	const auto alone = PathSmoother::run(c.in, p);
	EXPECT_EQ(alone.duplicates, 0u);
	EXPECT_GT(Corridor::worst(alone.path, c.truth), 0.01);
}

TEST(PathSmoother, ATableKeepsItsShapeAcrossABlindStep)
{
	// The corridor with exact odometry and a blind step (ALegMappedTwiceIsHeldToOnePlace), the
	// end wall replaced by a table right of the path, centred at (2.925, -0.4): before the blind
	// step the robot touches its leg at (2.425, -0.1) on the -x and +y faces, after it only the
	// leg at (3.425, -0.7), on the same faces. The particle mapped the table 5 cm short along x.
	// Each leg alone, the second half of the path and the far leg's shift share those 5 cm; the
	// table's known size (eq. S7) puts the far leg where the near one says, and the path on the
	// truth.
	Corridor c;
	c.blindStep(c.in.covariances[1]);
	for (size_t i = 21; i < c.truth.size(); i++) c.in.path[i][0] -= 0.03;  // the start: the truth
	world::Table t;
	t.x = 2.925 - 0.05, t.y = -0.4, t.length = 1, t.width = 0.6, t.leg_width = 0.05;
	c.in.solids.pop_back();
	for (int k = 0; k < 4; k++) c.in.solids.push_back(t.leg(k, 0));
	auto& contacts = c.in.contacts;
	std::vector<baseline::Contact> faces;
	for (size_t i = 0; i < contacts.size(); i += 2)  // [i] the side wall, [i + 1] ahead
	{
		const double x = c.truth[contacts[i].sweep][0];
		const Eigen::Vector2d leg =
			contacts[i].sweep <= 20 ? Eigen::Vector2d(2.425, -0.1) : Eigen::Vector2d(3.425, -0.7);
		auto& ahead = contacts[i + 1];  // the leg's -x face
		ahead.p = {leg.x() - 0.025 - x, leg.y()}, ahead.shaft = ahead.p.normalized();
		baseline::Contact side = ahead;  // its +y face
		side.p = {leg.x() - x, leg.y() + 0.025}, side.normal = M_PI / 2, side.shaft = side.p.normalized();
		faces.push_back(side);
	}
	contacts.insert(contacts.end(), faces.begin(), faces.end());
	smooth::TSmoothParams p;
	p.gate = 0.08;  // the table is mapped 5 cm off
	const auto alone = PathSmoother::run(c.in, p);
	EXPECT_EQ(alone.tied, contacts.size());
	EXPECT_GT(Corridor::worst(alone.path, c.truth), 0.015);
	p.table_sigma = 0.005;
	const auto shaped = PathSmoother::run(c.in, p);
	EXPECT_EQ(shaped.tied, contacts.size());
	EXPECT_LT(Corridor::worst(shaped.path, c.truth), 0.002);
}

TEST(PathSmoother, AWallMappedTwiceIsHeldToOneLine)
{
	// ALegMappedTwiceIsHeldToOnePlace with the end wall itself: the second half of the path
	// drifted 3 cm along x across the blind step and mapped the end wall a second time, 3 cm
	// further (every piece its own group: wall_merge 0). DuplicateWalls pairs the two pieces
	// (parallel, overlapping, touched from the same side); held to one line (eq. S5), the path
	// is the truth; left apart, the copy and the second half share the 3 cm.
	Corridor c;
	c.blindStep(c.in.covariances[1]);
	c.in.solids[1] = world::Obstacle::rectangle({2.45, 0}, M_PI / 2, 1, 0.05, 0.5);  // face at x = 2.4
	c.in.solids.push_back(world::Obstacle::rectangle({2.48, 0}, M_PI / 2, 1, 0.05, 0.5));  // the copy: x = 2.43
	smooth::TSmoothParams p;
	p.wall_merge = 0;
	const auto held = PathSmoother::run(c.in, p);
	EXPECT_EQ(held.duplicateWalls, 1u);
	EXPECT_EQ(held.duplicateWallsApart, 0u);
	EXPECT_EQ(held.duplicates, 0u);
	EXPECT_EQ(held.tied, c.in.contacts.size());
	EXPECT_LT(Corridor::worst(held.path, c.truth), 0.001);
	EXPECT_NEAR(2.4 + held.shifts[held.groupOf[1]].x(), 2.43 + held.shifts[held.groupOf[2]].x(), 0.001);
	p.duplicate_wall_distance = 0;
	const auto alone = PathSmoother::run(c.in, p);
	EXPECT_EQ(alone.duplicateWalls + alone.duplicateWallsApart, 0u);
	EXPECT_GT(Corridor::worst(alone.path, c.truth), 0.01);
}

TEST(PathSmoother, LegsOfTwoTablesSideBySideAreLeftApart)
{
	// The corridor with odometry good to 0.1 mm a step, the end wall replaced by two real
	// tables' legs: the first half of the path touches the one whose face is at x = 2.4
	// straight ahead, the second half one 7 cm to its left whose face is at x = 2.43. Their
	// centres lie 7.6 cm apart, so DuplicateLegs pairs them (duplicate_distance 0.08). Holding
	// them to one place costs more than leaving each where its contacts put it (eq. S6).
	Corridor c;
	for (size_t i = 1; i < c.truth.size(); i++)
		c.in.increments[i] = {0.05, 0, 0}, c.in.covariances[i] = 1e-8 * Eigen::Matrix3d::Identity();
	c.in.path = c.truth;
	for (auto& k : c.in.contacts)
		if (k.normal == M_PI && k.sweep > 20) k.p = {2.43 - c.truth[k.sweep][0], 0.07};
	c.endLegs({0.03, 0.07});  // the second leg 2 at (2.455, 0.07)
	c.expectDecided(PathSmoother::run(c.in, smooth::TSmoothParams()), 0, 1, {3, 7});
}

TEST(PathSmoother, EachTableMappedTwiceIsDecidedOnItsOwn)
{
	// ALegMappedTwiceIsHeldToOnePlace's corridor (odometry good to 1 mm a step but for the
	// blind step; the second half mapped the end leg a second time, 3 cm further), plus two
	// real legs of two other tables to the right of the first half, 6.7 cm apart: sweeps 0-9
	// touch one (its face at y = -0.3), sweeps 10-20 the other (face at y = -0.33). DuplicateLegs
	// pairs both; eq. S6 holds the copy and leaves the two real legs apart.
	Corridor c;
	c.blindStep(0.01 * c.in.covariances[1]);
	c.endLegs({0.03, 0});
	for (uint32_t i = 0; i <= 20; i++)
	{
		baseline::Contact right;
		const double x = c.truth[i][0];
		right.p = i < 10 ? Eigen::Vector2d(0.5 - x, -0.3) : Eigen::Vector2d(0.56 - x, -0.33);
		right.normal = M_PI / 2, right.shaft = {0, -1}, right.sigma_r = 0.002, right.sweep = i;
		c.in.contacts.push_back(right);
	}
	c.in.solids.push_back(world::Obstacle::rectangle({0.5, -0.325}, 0, 0.025, 0.025, 0.5, 2, 0));
	c.in.solids.push_back(world::Obstacle::rectangle({0.56, -0.355}, 0, 0.025, 0.025, 0.5, 3, 0));
	c.expectDecided(PathSmoother::run(c.in, smooth::TSmoothParams()), 1, 1, {9, 10});
}

TEST(PathSmoother, OdometryToldExactIsKept)
{
	// Every increment's covariance zero (whisker-slam's odometry_model = exact): the path is
	// the odometry's chain from the start, although the end wall, mapped 10 cm off, pulls.
	Corridor c;
	for (auto& cov : c.in.covariances) cov.setZero();
	c.in.path = c.truth;  // not the chain: the result must not depend on the start estimate
	smooth::TSmoothParams p;
	p.gate = 0.15;
	const auto r = PathSmoother::run(c.in, p);
	EXPECT_EQ(r.rounds, 0u);
	EXPECT_LT(Corridor::worst(r.path, c.odometry), 1e-12);
}

TEST(PathSmoother, AStretchLockedOntoTheWrongLegsIsBridged)
{
	// A row of posts 0.5 m apart, 0.4 m to the left of a robot driving 5 m along +x; each sweep
	// touches the next post ahead twice: its near face (x) and its bottom face (y). The start
	// path (a filter's) is the truth but for sweeps 40-60, locked one post ahead: every
	// contact there ties to the wrong post exactly, and only the odometry says otherwise.
	const size_t n = 101;
	PathSmoother::TInput in;
	std::vector<Eigen::Vector3d> truth;
	for (int k = 0; k < 12; k++)
		in.solids.push_back(world::Obstacle::rectangle({0.5 * k + 0.25, 0.4}, 0, 0.025, 0.025, 0.5, k, 0));
	for (size_t i = 0; i < n; i++)
	{
		const double x = 0.05 * static_cast<double>(i);
		truth.emplace_back(x, 0, 0);
		in.increments.emplace_back(i ? 0.05 : 0, 0, 0);
		in.covariances.push_back(Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal());
		const double post = 0.5 * std::ceil((x + 0.075 - 0.25) / 0.5) + 0.25;  // the next post whose face is 5 cm ahead
		baseline::Contact face, bottom;
		face.p = {post - 0.025 - x, 0.4}, face.normal = M_PI;
		bottom.p = {post - x, 0.375}, bottom.normal = -M_PI / 2;
		for (auto* c : {&face, &bottom})
			c->shaft = c->p.normalized(), c->sigma_r = 0.002, c->sweep = static_cast<uint32_t>(i), in.contacts.push_back(*c);
		const double locked = 0.1 * static_cast<double>(std::clamp<long>(static_cast<long>(i) - 35, 0, 5) -
														std::clamp<long>(static_cast<long>(i) - 60, 0, 5));
		in.path.emplace_back(x + locked, 0, 0);
	}
	ASSERT_NEAR(Corridor::worst(in.path, truth), 0.5, 1e-9);
	smooth::TSmoothParams p;
	p.bridge_gate = 0;
	const auto refined = PathSmoother::run(in, p);
	EXPECT_GT(Corridor::worst(refined.path, truth), 0.2);  // the smoother alone keeps the lock
	EXPECT_EQ(refined.bridges, 0u);
	EXPECT_GT(refined.strayMax, 5);
	p.bridge_gate = smooth::TSmoothParams{}.bridge_gate;
	const auto bridged = PathSmoother::run(in, p);
	EXPECT_GE(bridged.bridges, 1u);
	EXPECT_GE(bridged.bridgesTried, bridged.bridges);
	EXPECT_EQ(bridged.tied, in.contacts.size());
	EXPECT_LT(Corridor::worst(bridged.path, truth), 0.002);
	EXPECT_LT(bridged.strayMax, 1e-3);  // the truth is the odometry's chain here
	// A long window the path cannot fill finds nothing; a short one beside it bridges as well.
	p.bridge_window = 200;
	EXPECT_EQ(PathSmoother::run(in, p).bridgesTried, 0u);
	p.bridge_short_window = 40;
	const auto shortBridged = PathSmoother::run(in, p);
	EXPECT_GE(shortBridged.bridges, 1u);
	EXPECT_LT(Corridor::worst(shortBridged.path, truth), 0.002);
	p.bridge_window = 40, p.bridge_short_window = 0;
	// From the truth nothing strays: nothing is tried, and the path stays.
	in.path = truth;
	const auto kept = PathSmoother::run(in, p);
	EXPECT_EQ(kept.bridgesTried, 0u);
	EXPECT_LT(Corridor::worst(kept.path, truth), 1e-6);
}

TEST(PathSmoother, AStretchMappedWithItsCopyMovesAsOne)
{
	// A robot driving 5 m along +x past a row of posts 0.5 m apart on its left, and back, away
	// from and towards a wall across its line whose face is at x = -0.5. Each sweep touches the
	// next post ahead (its near and bottom faces), and the wall within 1 m. The start path (a
	// filter's) locked one post ahead at sweep 170, on the way back, and stayed there to the
	// end: its contacts tie to the wrong posts exactly, and it mapped the wall a second time,
	// 0.5 m beyond the first. Holding the two walls as one (eq. S5) from that path drags the copy
	// off its contacts, so eq. S6 leaves them apart; moving the stretch with its copy onto the
	// first (eq. S9) finds the truth. (Eq. S8 would bridge this stretch too, from the exact
	// odometry; it is off, to see eq. S9 alone.)
	const size_t n = 202;
	PathSmoother::TInput in;
	std::vector<Eigen::Vector3d> truth;
	in.solids.push_back(world::Obstacle::rectangle({-0.525, 0}, M_PI / 2, 0.3, 0.025, 0.5));  // the wall, face x = -0.5
	in.solids.push_back(world::Obstacle::rectangle({-1.025, 0}, M_PI / 2, 0.3, 0.025, 0.5));  // its copy
	for (int k = 0; k < 12; k++)
		in.solids.push_back(world::Obstacle::rectangle({0.5 * k + 0.25, 0.4}, 0, 0.025, 0.025, 0.5, k, 0));
	for (size_t i = 0; i < n; i++)
	{
		const bool back = i > 100;
		const double x = back ? 5 - 0.05 * static_cast<double>(i - 101) : 0.05 * static_cast<double>(i);
		const double s = back ? -1 : 1;  // robot frame = world frame mirrored on the way back
		truth.emplace_back(x, 0, back ? M_PI : 0);
		in.increments.emplace_back(i == 101 ? 0 : i ? 0.05 : 0, 0, i == 101 ? M_PI : 0);
		in.covariances.push_back(Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal());
		// The next post whose near face is 5 cm ahead, if there is one.
		const double post = back ? 0.5 * std::floor((x - 0.075 - 0.25) / 0.5) + 0.25
								 : 0.5 * std::ceil((x + 0.075 - 0.25) / 0.5) + 0.25;
		baseline::Contact face, bottom, wall;
		face.p = {s * (post - s * 0.025 - x), s * 0.4}, face.normal = M_PI;
		bottom.p = {s * (post - x), s * 0.375}, bottom.normal = -s * M_PI / 2;
		wall.p = {s * (-0.5 - x), 0}, wall.normal = back ? M_PI : 0;
		std::vector<baseline::Contact*> touched;
		if (post > 0 && post < 6) touched = {&face, &bottom};
		if (x <= 1) touched.push_back(&wall);
		for (auto* c : touched)
			c->shaft = c->p.normalized(), c->sigma_r = 0.002, c->sweep = static_cast<uint32_t>(i), in.contacts.push_back(*c);
		in.path.push_back(truth.back());
		if (back) in.path.back().x() -= 0.1 * static_cast<double>(std::clamp<long>(static_cast<long>(i) - 165, 0, 5));
	}
	smooth::TSmoothParams p;
	p.duplicate_wall_distance = 0.6;
	p.bridge_gate = 0;
	p.stretch_margin = 0;
	const auto apart = PathSmoother::run(in, p);
	EXPECT_EQ(apart.duplicateWalls, 0u);
	EXPECT_EQ(apart.duplicateWallsApart, 1u);
	EXPECT_EQ(apart.stretchesTried, 0u);
	EXPECT_GT(Corridor::worst(apart.path, truth), 0.4);  // eq. S6 keeps the lock
	p.stretch_margin = smooth::TSmoothParams{}.stretch_margin;
	const auto moved = PathSmoother::run(in, p);
	EXPECT_EQ(moved.duplicateWalls, 1u);
	EXPECT_EQ(moved.stretches, 1u);
	EXPECT_GE(moved.stretchesTried, moved.stretches);
	EXPECT_EQ(moved.tied, in.contacts.size());
	EXPECT_LT(Corridor::worst(moved.path, truth), 0.002);
	// From the truth the copy is touched by nothing: no pair, nothing tried, the path stays.
	in.path = truth;
	const auto kept = PathSmoother::run(in, p);
	EXPECT_EQ(kept.duplicateWalls + kept.duplicateWallsApart + kept.stretchesTried, 0u);
	EXPECT_LT(Corridor::worst(kept.path, truth), 1e-6);
}

TEST(PathSmoother, TurnsToldExactHoldAgainstContactsThatPull)
{
	// The corridor, each sweep touching the side wall twice, 0.2 m behind and ahead, but the
	// wall mapped 2 degrees askew: to fit both contacts a sweep must turn with it. Odometry with
	// heading noise lets the path turn towards the wall; odometry exact in heading (a gyro's
	// turns: the yaw variance zero, eq. S2's floor of 0.01 degree a step) keeps the turns.
	Corridor c;
	c.in.contacts.clear();
	for (size_t i = 0; i < c.truth.size(); i++)
		for (const double along : {-0.2, 0.2})
		{
			baseline::Contact side;
			side.p = {along, 0.3}, side.normal = -M_PI / 2, side.shaft = side.p.normalized(), side.sigma_r = 0.002;
			side.sweep = static_cast<uint32_t>(i);
			c.in.contacts.push_back(side);
		}
	c.in.solids = {world::Obstacle::rectangle({1.2, 0.35}, core::deg2rad(2), 1.5, 0.05, 0.5)};
	c.in.path = c.truth;
	smooth::TSmoothParams p;
	p.gate = 0.1;
	const auto maxTurn = [&](const PathSmoother::TResult& r) {
		double w = 0;
		for (size_t i = 1; i < r.path.size(); i++)
			w = std::max(w, std::abs(core::wrapToPi(r.path[i].z() - r.path[i - 1].z() - c.in.increments[i].z())));
		return core::rad2deg(w);
	};
	const auto loose = PathSmoother::run(c.in, p);
	for (auto& cov : c.in.covariances) cov(2, 2) = 0;
	const auto exact = PathSmoother::run(c.in, p);
	EXPECT_EQ(exact.tied, c.in.contacts.size());
	EXPECT_GT(core::rad2deg(loose.path.back().z()), 1);  // the path turned towards the askew wall
	EXPECT_GT(maxTurn(loose), 1);  // most of it in the first step
	// Told exact, each step turns within a few of eq. S2's floors (0.01 degree) of the odometry:
	// a map askew by 2 degrees under every sweep bends the 40 steps by 0.44 degrees in all.
	EXPECT_LT(maxTurn(exact), 0.05);
	EXPECT_LT(std::abs(core::rad2deg(exact.path.back().z())), 0.6);
}
