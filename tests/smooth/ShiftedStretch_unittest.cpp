#include <gtest/gtest.h>
#include <whiskermap/smooth/ShiftedStretch.h>

using namespace whiskermap;
using smooth::ShiftedStretch;

namespace
{
/** A contact of sweep `pose` tied to group `group`. */
smooth::ContactFactor tie(size_t pose, size_t group)
{
	smooth::ContactFactor f;
	f.pose = pose, f.group = group;
	return f;
}

/** 100 poses along x; groups 0 and 1 a leg mapped twice (1 is 0 shifted 0.2 m along x, both
 *  unshifted), 0 touched by sweeps 10-20, 1 by 50-60; group 2 touched by 52-58 alone, group 3 by
 *  55 and 90, group 4 untouched. */
struct Twice
{
	std::vector<Eigen::Vector3d> path;
	std::vector<Eigen::Vector2d> shifts = std::vector<Eigen::Vector2d>(5, Eigen::Vector2d::Zero());
	std::vector<smooth::ContactFactor> ties;
	std::vector<smooth::SameSolidFactor> set{{0, 1, {0.2, 0}, 0.005}};

	Twice()
	{
		for (size_t i = 0; i < 100; i++) path.emplace_back(0.05 * static_cast<double>(i), 0, 0.1);
		for (size_t i = 10; i <= 20; i++) ties.push_back(tie(i, 0));
		for (size_t i = 50; i <= 60; i++) ties.push_back(tie(i, 1));
		for (size_t i = 52; i <= 58; i++) ties.push_back(tie(i, 2));
		ties.push_back(tie(55, 3)), ties.push_back(tie(90, 3));
	}

	/** How far pose i moved along x (nothing else may move). */
	double moved(const std::vector<Eigen::Vector3d>& before, size_t i) const
	{
		EXPECT_DOUBLE_EQ(path[i].y(), before[i].y());
		EXPECT_DOUBLE_EQ(path[i].z(), before[i].z());
		return path[i].x() - before[i].x();
	}
};
}  // namespace

TEST(ShiftedStretch, TheStretchThatMappedTheCopyMovesWithItFadingAtItsEnds)
{
	Twice t;
	const auto before = t.path;
	ASSERT_TRUE(ShiftedStretch::move(t.path, t.shifts, t.ties, t.set, true, 10));  // eq. S9
	// The copy (1) lands on its twin; what only the stretch touched (2) moves with it; what
	// was touched outside it too (3), the twin (0) and the untouched (4) stay.
	EXPECT_TRUE(t.shifts[1].isApprox(Eigen::Vector2d(0.2, 0)));
	EXPECT_TRUE(t.shifts[2].isApprox(Eigen::Vector2d(0.2, 0)));
	for (const size_t g : {0, 3, 4}) EXPECT_EQ(t.shifts[g], Eigen::Vector2d::Zero()) << "group " << g;
	for (size_t i = 0; i <= 40; i++) EXPECT_DOUBLE_EQ(t.moved(before, i), 0) << "pose " << i;
	EXPECT_NEAR(t.moved(before, 45), 0.1, 1e-12);
	for (size_t i = 50; i <= 60; i++) EXPECT_NEAR(t.moved(before, i), 0.2, 1e-12) << "pose " << i;
	EXPECT_NEAR(t.moved(before, 63), 0.14, 1e-12);
	for (size_t i = 70; i < 100; i++) EXPECT_DOUBLE_EQ(t.moved(before, i), 0) << "pose " << i;
}

TEST(ShiftedStretch, EitherSideMovesTheStartNeverAndAStretchAtTheEndMovesToIt)
{
	// The first copy onto the second: its stretch (10-20) ramps from pose 0, which stays (the
	// known start); a margin reaching past the path's end moves everything after the stretch.
	Twice t;
	auto before = t.path;
	ASSERT_TRUE(ShiftedStretch::move(t.path, t.shifts, t.ties, t.set, false, 15));
	EXPECT_TRUE(t.shifts[0].isApprox(Eigen::Vector2d(-0.2, 0)));
	for (const size_t g : {1, 2, 3, 4}) EXPECT_EQ(t.shifts[g], Eigen::Vector2d::Zero()) << "group " << g;
	EXPECT_DOUBLE_EQ(t.moved(before, 0), 0);
	EXPECT_NEAR(t.moved(before, 5), -0.1, 1e-12);
	EXPECT_NEAR(t.moved(before, 15), -0.2, 1e-12);
	EXPECT_DOUBLE_EQ(t.moved(before, 35), 0);
	Twice end;
	before = end.path;
	ASSERT_TRUE(ShiftedStretch::move(end.path, end.shifts, end.ties, end.set, true, 40));
	for (size_t i = 50; i < 100; i++) EXPECT_NEAR(end.moved(before, i), 0.2, 1e-12) << "pose " << i;
}

TEST(ShiftedStretch, AWallMovesAcrossOnlyAndACopyNothingTouchedMovesNothing)
{
	Twice t;
	t.set[0].offset = {0.2, 0.5}, t.set[0].P = Eigen::Vector2d(1, 0) * Eigen::RowVector2d(1, 0);  // a wall across x
	ASSERT_TRUE(ShiftedStretch::move(t.path, t.shifts, t.ties, t.set, true, 10));
	EXPECT_TRUE(t.shifts[1].isApprox(Eigen::Vector2d(0.2, 0)));
	Twice none;
	none.ties.erase(std::remove_if(none.ties.begin(), none.ties.end(), [](const auto& f) { return f.group == 1; }),
					none.ties.end());
	const auto before = none.path;
	EXPECT_FALSE(ShiftedStretch::move(none.path, none.shifts, none.ties, none.set, true, 10));
	EXPECT_EQ(none.path, before);
	for (const auto& d : none.shifts) EXPECT_EQ(d, Eigen::Vector2d::Zero());
}
