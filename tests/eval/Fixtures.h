#pragma once
#include "../TempDirTest.h"

#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/world/Table.h>

#include <string>

namespace whiskermap::test
{
/** A paper-sized table (1.0 x 0.6 m, 5 cm legs) at (x, y, yaw_deg). */
inline world::Table table(double x, double y, double yawDeg)
{
	world::Table t;
	t.x = x, t.y = y, t.yaw = core::deg2rad(yawDeg);
	t.length = 1.0, t.width = 0.6, t.leg_width = 0.05, t.texture = 0.7;
	return t;
}
}  // namespace whiskermap::test
