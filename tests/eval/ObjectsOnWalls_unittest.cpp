// Issue 11: the map's objects standing on a wall (an interior wall's slab, or outside the arena).
#include "Fixtures.h"

#include <whiskermap/eval/ObjectsOnWalls.h>

using namespace whiskermap;
using eval::ObjectsOnWalls;

TEST(ObjectsOnWalls, ALegInAWallsSlabOrOutsideTheArenaPutsItsObjectOnAWall)
{
	world::World w;
	w.x_min = 0, w.x_max = 6, w.y_min = 0, w.y_max = 4;
	world::Wall wall;  // along y = 2 from x = 3 to 6, 0.1 m thick: its slab is y in [1.95, 2.05]
	wall.x0 = 3, wall.y0 = 2, wall.x1 = 6, wall.y1 = 2, wall.thickness = 0.1;
	w.walls.push_back(wall);
	// A 1.0 x 0.6 table with 5 cm legs at yaw 0: its legs' squares reach y +- 0.325.
	const std::vector<world::Table> est{
		test::table(1.5, 2, 0),  // west of the wall's end: free
		test::table(4.5, 2.37, 0),  // its south legs reach y = 2.045: into the slab
		test::table(4.5, 2.38, 0),  // they reach y = 2.055: 5 mm clear
		test::table(0.52, 1, 0),  // its west legs reach x = -0.005: past the arena's wall
		test::table(50, 50, 0),  // far outside the arena
		test::table(4.5, 2, 90),  // across the wall, its legs at y = 2 +- 0.5 either side of it: they stand clear
	};
	EXPECT_EQ(ObjectsOnWalls::of(w, est), (std::vector<size_t>{1, 3, 4}));
	EXPECT_TRUE(ObjectsOnWalls::of(w, {}).empty());
}
