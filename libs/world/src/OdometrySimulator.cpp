#include <whiskermap/core/SeedStream.h>
#include <whiskermap/world/OdometrySimulator.h>

#include <cmath>

namespace whiskermap::world
{
namespace
{
constexpr uint64_t ODOMETRY_STREAM = 1;  // the sensor noise uses the seed itself
}

OdometrySimulator::OdometrySimulator(OdometryNoise noise, uint64_t seed)
	: m_noise(std::move(noise)), m_rng(core::seedStream(seed, ODOMETRY_STREAM))
{
}

mrpt::poses::CPose2D OdometrySimulator::corrupt(const mrpt::poses::CPose2D& u)
{
	const double s = 1 + m_noise.scale_bias, x = s * u.x(), y = s * u.y(), phi = u.phi();
	// MRPT's Gaussian odometry model (CActionRobotMovement2D, mmGaussian) with random-walk std-devs:
	// cov = J diag(sxy^2, sxy^2, sphi^2) J^T, J = [R(dphi/2) | d(x, y)/d(phi)]: draw e ~ N(0, diag), add J e.
	const double d = std::hypot(x, y);
	const double sxy = m_noise.sigmaXY(d, phi), sphi = m_noise.sigmaPhi(d, phi);
	const double ex = sxy * m_rng.drawGaussian1D_normalized();
	const double ey = sxy * m_rng.drawGaussian1D_normalized();
	const double ephi = sphi * m_rng.drawGaussian1D_normalized();
	const double c = std::cos(phi / 2), sn = std::sin(phi / 2);
	return mrpt::poses::CPose2D(
		x + c * ex - sn * ey + (-sn * x - c * y) * ephi,
		y + sn * ex + c * ey + (c * x - sn * y) * ephi, phi + ephi);
}

mrpt::poses::CPose2D OdometrySimulator::next(const mrpt::poses::CPose2D& truth)
{
	if (m_noise.exact()) return truth;
	if (!m_lastTruth)
		m_odometry = truth;  // the start is known
	else
		m_odometry = m_odometry + corrupt(truth - *m_lastTruth);
	m_odometry.normalizePhi();
	m_lastTruth = truth;
	return m_odometry;
}
}  // namespace whiskermap::world
