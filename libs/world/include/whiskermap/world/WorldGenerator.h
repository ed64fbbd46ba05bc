#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/TSensorNoise.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/TouchAudit.h>
#include <whiskermap/world/World.h>

#include <cstdint>
#include <string>
#include <vector>

namespace whiskermap::world
{
/** Generates the evaluation worlds and their robot paths (doc/eval-worlds.md), one category
 *  at a time, deterministically from a seed. Tables are the paper's known table (1.0 x 0.6 m
 *  leg spacing, 5 cm legs, texture 0.7), walls texture 0.3; layouts are drawn at random,
 *  rejected until they obey their category's rules, and every path pose is free.
 *
 *  Categories: random_yaw, clutter, side_by_side, large (grid paths) and sparse (a path that
 *  touches one leg at a time, so that no `window` consecutive contacts hold two legs of one
 *  table, checked with the simulator's truth at every noise level given); issue 11's walls
 *  (random interior walls), mixed_classes (tables, desks and chairs at random yaw),
 *  near_walls (both, every object 5-25 cm from a wall), sized_classes (mixed_classes with
 *  each object's length and width within +-3 cm of its class's) and varied_legs (sized_classes
 *  with each object's leg width within +-1 cm and texture within +-0.1 of its class's), on
 *  grid paths. */
class WorldGenerator
{
   public:
	struct TSettings
	{
		Robot robot;
		/** Sparse paths are verified with the simulator at each of these noise levels. */
		std::vector<obs::TSensorNoise> noises{obs::TSensorNoise{}};
		/** The seed whisker-sim will be run with (--seed) when the paths are verified. */
		uint64_t simSeed = 1;
		/** The map's working memory, in shapelets (config/whisker-map.ini memory_size). */
		size_t window = 7;
		/** Layouts (each with its path) tried before giving up. */
		int maxAttempts = 200;
	};

	/** A generated world, its path and what the path touches. */
	struct Scenario
	{
		std::string category;
		uint64_t seed = 0;
		int attempt = 0;  ///< 1-based index of the accepted layout
		World world;
		std::vector<mrpt::poses::CPose2D> path;
		size_t droppedPoses = 0;  ///< blocked grid poses left out of the path
		TouchAudit audit;  ///< the path's contacts (noiseless run; truth is the same at any noise)
		double closestGap = 0;  ///< smallest footprint gap between two tables, metres
		std::string verified;  ///< how the path was checked (noise levels, seed, window)

		/** Several lines: category, seed, layout and path facts, identifiability. */
		std::string description() const;
	};

	/** The category names, in the order they are documented. */
	static const std::vector<std::string>& categories();

	explicit WorldGenerator(TSettings s) : m_s(std::move(s)) {}

	/** Throws core::Error for an unknown category or when no layout is accepted. */
	Scenario generate(const std::string& category, uint64_t seed) const;

   private:
	TSettings m_s;
};
}  // namespace whiskermap::world
