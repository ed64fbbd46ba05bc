#pragma once
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/datetime.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>
#include <whiskermap/world/Robot.h>
#include <whiskermap/world/World.h>

#include <vector>

namespace whiskermap::world
{
/** Simulates whisker sweeps in a World: exact 2-D contact geometry (WhiskerContact) against
 *  legs and walls, then Gaussian reading noise (paper eqs. 1-3). Seeded: the same seed and
 *  the same calls give the same observations. */
class WhiskerSimulator
{
   public:
	/** What each whisker really touched, for evaluation and statistics. */
	struct Truth
	{
		int table = -1;  ///< table index, or -1 (wall or nothing)
		int leg = -1;  ///< leg index within the table, or -1
		bool wall = false;
	};

	WhiskerSimulator(World world, Robot robot, obs::TSensorNoise noise, uint64_t seed);

	/** False when the robot body at this pose would overlap a leg or stand outside the walls. */
	bool poseIsFree(const mrpt::poses::CPose2D& pose) const;

	/** One whisk at `pose`; `truth` (optional) receives one entry per whisker. */
	obs::CObservationWhiskerContacts::Ptr sense(
		const mrpt::poses::CPose2D& pose, mrpt::Clock::time_point stamp,
		std::vector<Truth>* truth = nullptr);

	const World& world() const { return m_world; }
	const Robot& robot() const { return m_robot; }

   private:
	World m_world;
	Robot m_robot;
	obs::TSensorNoise m_noise;
	std::vector<Obstacle> m_obstacles;
	mrpt::random::CRandomGenerator m_rng;
};
}  // namespace whiskermap::world
