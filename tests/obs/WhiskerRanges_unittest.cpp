#include <gtest/gtest.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3D.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/WhiskerRanges.h>

#include <cmath>

#include "SampleSweep.h"

using whiskermap::obs::CObservationWhiskerContacts;
using whiskermap::obs::TWhisker;
using whiskermap::obs::WhiskerRanges;

namespace
{
CObservationWhiskerContacts sweep() { return whiskermap::test::sampleSweep(-0.03, 0.04); }

/** The occupancy probability of the grid cell at world point (x, y), 0.5 unknown. (MRPT's
 *  getPos() is the probability that the cell is FREE.) */
float occupied(const mrpt::maps::COccupancyGridMap2D& g, double x, double y) { return 1.0f - g.getPos(x, y); }
}  // namespace

TEST(WhiskerRanges, OneRayPerWhiskerFromItsBaseAlongItsShaft)
{
	const auto rays = WhiskerRanges::fromSweep(sweep());
	ASSERT_EQ(rays.size(), 2u);
	for (size_t i = 0; i < 2; i++)
	{
		const auto& r = *rays[i];
		EXPECT_EQ(r.timestamp, sweep().timestamp);
		EXPECT_EQ(r.sensorLabel, "WHISKERS_RANGE_" + std::to_string(i));
		ASSERT_EQ(r.sensedData.size(), 1u);
		EXPECT_EQ(r.sensedData[0].sensorID, i);
		EXPECT_LT(r.maxSensorDistance, 0.6f);  // the full length is no return
		EXPECT_GT(r.maxSensorDistance, 0.6f - 1e-6f);
		EXPECT_NEAR(r.sensorConeApperture, WhiskerRanges::CONE_APERTURE_DEG * M_PI / 180, 1e-9);
	}
	// range: the contact distance, or the whisker length when it touched nothing
	EXPECT_FLOAT_EQ(rays[0]->sensedData[0].sensedDistance, 0.25f);
	EXPECT_FLOAT_EQ(rays[1]->sensedData[0].sensedDistance, 0.6f);
	// sensor pose: the whisker base on the robot (sensorPose + mount), yaw = shaft angle
	const auto& p0 = rays[0]->sensedData[0].sensorPose;
	EXPECT_NEAR(p0.x, 0.05, 1e-12);
	EXPECT_NEAR(p0.y, 0.04, 1e-12);
	EXPECT_NEAR(p0.yaw, M_PI / 2, 1e-12);
	const auto& p1 = rays[1]->sensedData[0].sensorPose;
	EXPECT_NEAR(p1.x, 0.05, 1e-12);
	EXPECT_NEAR(p1.y, -0.04, 1e-12);
	EXPECT_NEAR(p1.yaw, -0.2, 1e-12);
}

TEST(WhiskerRanges, TheSensorPoseOfTheSweepRotatesTheBases)
{
	auto s = sweep();
	s.sensorPose = mrpt::poses::CPose3D(0.1, 0.2, 0, M_PI / 2, 0, 0);
	const auto rays = WhiskerRanges::fromSweep(s);
	const auto& p = rays[0]->sensedData[0].sensorPose;
	EXPECT_NEAR(p.x, 0.1 - 0.04, 1e-12);  // mount (-0.03, 0.04) turned by 90 degrees
	EXPECT_NEAR(p.y, 0.2 - 0.03, 1e-12);
	EXPECT_NEAR(p.yaw, M_PI, 1e-12);
}

TEST(WhiskerRanges, OnlyContactsBecomePointsOfTheLikelihoodField)
{
	// MRPT's likelihood field scores a CObservationRange through a points map of it: the
	// contact must give a point at its place, the no-return none.
	const auto rays = WhiskerRanges::fromSweep(sweep());
	mrpt::maps::CSimplePointsMap touched, untouched;
	touched.insertObservation(*rays[0]);
	untouched.insertObservation(*rays[1]);
	ASSERT_GE(touched.size(), 1u);
	for (size_t k = 0; k < touched.size(); k++)
	{
		float x, y, z;
		touched.getPoint(k, x, y, z);
		EXPECT_NEAR(x, 0.05, 0.002);  // 0.25 m left of the base at (0.05, 0.04)
		EXPECT_NEAR(y, 0.29, 0.002);
	}
	EXPECT_EQ(untouched.size(), 0u);
}

TEST(WhiskerRanges, MrptsGridMarksTheContactOccupiedAndTheShaftsFree)
{
	mrpt::maps::COccupancyGridMap2D grid(-1, 1, -1, 1, 0.02);
	grid.insertionOptions.maxDistanceInsertion = 0.6f;  // = the whisker length, as config/grid-*.ini
	grid.insertionOptions.wideningBeamsWithDistance = false;
	mrpt::obs::CSensoryFrame sf;
	for (const auto& r : WhiskerRanges::fromSweep(sweep())) sf.insert(r);
	const mrpt::poses::CPose3D robot(0.1, -0.2, 0, 0, 0, 0);
	sf.insertObservationsInto(grid, robot);
	// whisker 0: base (0.15, -0.16), contact 0.25 m up at (0.15, 0.09); its shaft is free
	EXPECT_GT(occupied(grid, 0.15, 0.09), 0.5f);
	for (double y = -0.14; y < 0.07; y += 0.02) EXPECT_LT(occupied(grid, 0.15, y), 0.5f) << "y " << y;
	// whisker 1: base (0.15, -0.24), 0.6 m at -0.2 rad, no return: no occupied cell on it (MRPT
	// fills a slanted 0.1-degree cone sparsely: not every cell of it is marked free)
	const double c = std::cos(-0.2), s = std::sin(-0.2);
	int freeCells = 0;
	for (double d = 0.03; d <= 0.6; d += 0.01)
	{
		EXPECT_LE(occupied(grid, 0.15 + d * c, -0.24 + d * s), 0.5f) << "d " << d;
		freeCells += occupied(grid, 0.15 + d * c, -0.24 + d * s) < 0.5f;
	}
	EXPECT_GE(freeCells, 3);
	// away from both rays: unknown
	EXPECT_FLOAT_EQ(occupied(grid, -0.5, 0.5), 0.5f);
}

TEST(WhiskerRanges, AnInvalidSweepIsRefused)
{
	auto s = sweep();
	s.whiskers[0].r = 0.7;  // beyond the whisker
	EXPECT_THROW(WhiskerRanges::fromSweep(s), whiskermap::core::Error);
}
