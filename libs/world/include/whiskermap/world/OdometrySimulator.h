#pragma once
#include <mrpt/poses/CPose2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/world/OdometryNoise.h>

#include <optional>

namespace whiskermap::world
{
/** Dead reckoning along a true path: each step's true increment, scaled by the bias and
 *  perturbed by a draw from MRPT's Gaussian odometry model with OdometryNoise's random-walk
 *  std-devs, is composed onto the previous odometry pose. The first pose is known (odometry = truth there). Seeded from
 *  its own stream: the same seed and the same path give the same odometry, and the sensor
 *  noise of a run is the same whatever the odometry preset. */
class OdometrySimulator
{
   public:
	OdometrySimulator(OdometryNoise noise, uint64_t seed);

	/** The odometry recorded at the next true pose of the path. With exact odometry it is
	 *  the true pose itself (bit for bit). */
	mrpt::poses::CPose2D next(const mrpt::poses::CPose2D& truth);

	/** The recorded increment for a true increment `u` (one step's error; exposed for tests). */
	mrpt::poses::CPose2D corrupt(const mrpt::poses::CPose2D& u);

	const OdometryNoise& noise() const { return m_noise; }

   private:
	OdometryNoise m_noise;
	mrpt::random::CRandomGenerator m_rng;
	std::optional<mrpt::poses::CPose2D> m_lastTruth;
	mrpt::poses::CPose2D m_odometry;
};
}  // namespace whiskermap::world
