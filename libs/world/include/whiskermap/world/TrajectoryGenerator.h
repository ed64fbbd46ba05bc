#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/World.h>

#include <string>
#include <vector>

namespace whiskermap::world
{
/** What continuous trajectory to generate (whisker-sim --trajectory; doc/sensor-model.md). */
struct TrajectorySpec
{
	enum class Kind
	{
		Lawnmower,  ///< back and forth along x, rows `spacing` apart, `standoff` from the walls
		Explore,  ///< to random free places one after another (random exploration)
		WallFollow,  ///< counter-clockwise round the arena, `standoff` from the walls
		Loop  ///< a random closed tour round the arena's centre, ending at its start pose
	};
	Kind kind = Kind::Lawnmower;
	double speed = 0.4;  ///< m/s
	double rate = 8;  ///< sweeps per second: one pose every 1/rate s
	double turn_rate_deg = 90;  ///< largest heading change, degrees per second
	double duration = 0;  ///< seconds, 0 = no limit
	double length = 0;  ///< metres travelled, 0 = no limit
	double spacing = 0.5;  ///< lawnmower row spacing, metres
	double standoff = 0.25;  ///< robot centre to wall (lawnmower rows and ends, wall-follow), metres

	/** "lawnmower", "explore", "wall-follow", "loop"; throws core::Error otherwise. */
	static Kind parseKind(const std::string& name);
	/** Throws core::Error naming the first value out of range. */
	void validate() const;
};

/** Continuous robot paths through a world: poses one sweep apart (1/rate s) that move at
 *  most speed/rate and turn at most turn_rate/rate per step, and never put the robot body
 *  on a leg or a wall (they keep PathPlanner's clearance). A pattern (lawnmower, wall-follow,
 *  loop) ends after one pass, or repeats (lawnmower: back along its rows) until the
 *  duration or length is reached, then stops there; explore runs until the duration or
 *  length (120 s when neither is given). Places a pattern asks for that the body cannot
 *  reach are replaced by the nearest reachable place, and legs in the way are driven round
 *  (shortest free way). Seeded: the same world, spec and seed give the same poses. */
struct TrajectoryGenerator
{
	static std::vector<mrpt::poses::CPose2D> generate(
		const World& world, const Robot& robot, const TrajectorySpec& spec, uint64_t seed);
};
}  // namespace whiskermap::world
