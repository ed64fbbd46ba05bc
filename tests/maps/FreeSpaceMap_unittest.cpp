#include <gtest/gtest.h>
#include <whiskermap/maps/CHierarchicalObjectMap.h>
#include <whiskermap/obs/RawlogReader.h>

#include <algorithm>
#include <cmath>

using namespace whiskermap;
using maps::CHierarchicalObjectMap;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;
using TMode = CHierarchicalObjectMap::TInsertionOptions::TMode;

bool sameSector(const obs::SweptSector& a, const obs::SweptSector& b)
{
	constexpr double EPS = 1e-12;  // the map's pose went through a CPose3D
	return std::abs(a.x - b.x) < EPS && std::abs(a.y - b.y) < EPS && a.radius == b.radius &&
		   std::abs(a.from - b.from) < EPS && std::abs(a.span - b.span) < EPS;
}
}  // namespace

// Per-pose steps get the swept sectors of the working memory's sweeps (eq. 21) when the model's
// free_space is on, ending with the newest sweep's; none when off. A copy continues identically.
TEST(FreeSpaceMap, PerPoseStepsCarryTheMemorysSweptSectors)
{
	const auto rawlog = obs::RawlogReader::read(SRC + "/datasets/paper_arena/default.rawlog");
	CHierarchicalObjectMap on, off;
	on.insertionOptions.mode = off.insertionOptions.mode = TMode::PerPose;
	on.modelParams.free_space = true;
	size_t most = 0, withSectors = 0;
	for (size_t i = 0; i < 40; i++)
	{
		const auto& s = rawlog.sweeps[i];
		on.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		off.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		EXPECT_TRUE(off.lastInput().swept.empty());
		const auto newest = s.obs->toSweptSectors(s.robotPose);
		const auto& swept = on.lastInput().swept;
		withSectors += !newest.empty();
		ASSERT_GE(swept.size(), newest.size());
		for (size_t k = 0; k < newest.size(); k++)
			EXPECT_TRUE(sameSector(swept[swept.size() - newest.size() + k], newest[k])) << "sweep " << i;
		most = std::max(most, swept.size());
	}
	// Near the arena walls every whisker of a grid pose already crosses the wall when its whisk
	// starts (it stops at once): 12 of these 40 sweeps swept nothing.
	EXPECT_GT(withSectors, 20u);
	EXPECT_GT(most, rawlog.sweeps[0].obs->whiskers.size());  // older sweeps were kept too
	EXPECT_LE(most, 8 * rawlog.sweeps[0].obs->whiskers.size());  // at most memory_size + 1 sweeps
	CHierarchicalObjectMap copy = on;
	for (size_t i = 40; i < 80; i++)
	{
		const auto& s = rawlog.sweeps[i];
		on.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		copy.insertObservation(*s.obs, mrpt::poses::CPose3D(s.robotPose));
		EXPECT_EQ(on.lastRecord().logPosterior, copy.lastRecord().logPosterior);
	}
}
