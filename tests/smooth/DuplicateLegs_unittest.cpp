#include <gtest/gtest.h>
#include <whiskermap/smooth/DuplicateLegs.h>
#include <whiskermap/world/Table.h>

using namespace whiskermap;
using smooth::DuplicateLegs;
using Pairs = std::vector<std::pair<size_t, size_t>>;

namespace
{
/** A 1 x 0.6 m table with 5 cm legs, as mappedSolids() lists it: legs 0..3 tagged `id`. */
void addTable(std::vector<world::Obstacle>& solids, double x, double y, double yawDeg, int id)
{
	world::Table t;
	t.x = x, t.y = y, t.yaw = yawDeg * M_PI / 180, t.length = 1, t.width = 0.6, t.leg_width = 0.05, t.texture = 0.7;
	for (int k = 0; k < 4; k++) solids.push_back(t.leg(k, id));
}
}  // namespace

TEST(DuplicateLegs, OverlappingTablesArePairedLegByLeg)
{
	// One table mapped twice, 0.3 m apart, the second copy turned by 180 degrees (the same
	// table): each leg pairs with the leg at its place, whatever its corner index.
	std::vector<world::Obstacle> solids;
	addTable(solids, 1, 1, 20, 0);
	addTable(solids, 1.25, 1.17, 202, 1);
	solids.push_back(world::Obstacle::rectangle({3, 0}, M_PI / 2, 2, 0.05, 0.5));  // a wall: never paired
	const std::vector<bool> touched(solids.size(), true);
	EXPECT_EQ(DuplicateLegs::find(solids, touched, 0.1, 0.08), (Pairs{{0, 6}, {1, 7}, {2, 4}, {3, 5}}));
	// Two legs of a copy untouched: its footprint may stand on the wrong side, so only legs
	// within the distance pair (none here: the copies are 0.3 m apart).
	auto some = touched;
	some[4] = some[5] = false;
	EXPECT_TRUE(DuplicateLegs::find(solids, some, 0.1, 0.08).empty());
}

TEST(DuplicateLegs, NeighbouringTablesAreNotOneTable)
{
	// Two tables side by side 5 cm apart (their footprints overlap by the legs' half widths
	// but not once shrunk), and a touched leg 9 cm from the other table's nearest leg.
	std::vector<world::Obstacle> solids;
	addTable(solids, 1, 1, 0, 0);
	addTable(solids, 1, 1.69, 0, 1);  // legs at y = 1.3 and 1.39: 9 cm apart
	const std::vector<bool> touched(solids.size(), true);
	EXPECT_TRUE(DuplicateLegs::find(solids, touched, 0.1, 0.08).empty());
	// Closer than the distance: those legs are one leg.
	solids.clear();
	addTable(solids, 1, 1, 0, 0);
	addTable(solids, 1.2, 1.66, 0, 1);  // its legs 2, 3 at (0.7, 1.36) and (1.7, 1.36); table 0's 0, 1 at (1.5, 1.3), (0.5, 1.3)
	EXPECT_EQ(DuplicateLegs::find(solids, touched, 0.1, 0.08), (Pairs{}));
	solids.clear();
	addTable(solids, 1, 1, 0, 0);
	addTable(solids, 1.03, 1.65, 0, 1);  // legs 2, 3 at (0.53, 1.35), (1.53, 1.35): 5.8 cm from legs 1, 0
	EXPECT_EQ(DuplicateLegs::find(solids, touched, 0.1, 0.08), (Pairs{{0, 7}, {1, 6}}));
	auto some = touched;
	some[7] = false;  // an untouched leg is no evidence
	EXPECT_EQ(DuplicateLegs::find(solids, some, 0.1, 0.08), (Pairs{{1, 6}}));
}
