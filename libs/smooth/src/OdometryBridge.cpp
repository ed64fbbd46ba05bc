#include <whiskermap/core/Angles.h>
#include <whiskermap/smooth/OdometryBridge.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

namespace whiskermap::smooth
{
namespace
{
/** b's pose in a's frame. */
Eigen::Vector3d relative(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	const double c = std::cos(a[2]), s = std::sin(a[2]), dx = b[0] - a[0], dy = b[1] - a[1];
	return {c * dx + s * dy, -s * dx + c * dy, core::wrapToPi(b[2] - a[2])};
}

/** The Mahalanobis distance of the path's motion over sweeps a..b from the odometry's (eq. S8). */
double stray(const OdometryBridge::Path& path, const std::vector<OdometryFactor>& odometry, size_t a, size_t b)
{
	Eigen::Vector3d x = Eigen::Vector3d::Zero();
	Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
	for (size_t i = a + 1; i <= b; i++)
	{
		const auto& f = odometry[i];
		const double c = std::cos(x[2]), s = std::sin(x[2]);
		Eigen::Matrix3d J1, J2;  // of x (+) u with respect to x and to u
		J1 << 1, 0, -s * f.u[0] - c * f.u[1], 0, 1, c * f.u[0] - s * f.u[1], 0, 0, 1;
		J2 << c, -s, 0, s, c, 0, 0, 0, 1;
		C = J1 * C * J1.transpose() + J2 * f.covariance * J2.transpose();
		x = f.end(x);
	}
	Eigen::Vector3d e = relative(path[a], path[b]) - x;
	e[2] = core::wrapToPi(e[2]);
	return std::sqrt(e.dot(C.ldlt().solve(e)));
}
}  // namespace

std::vector<double> OdometryBridge::distances(
	const Path& path, const std::vector<OdometryFactor>& odometry, size_t window)
{
	std::vector<double> m;
	for (size_t a = 0; window > 0 && a + window < path.size(); a++) m.push_back(stray(path, odometry, a, a + window));
	return m;
}

std::vector<OdometryBridge::Stretch> OdometryBridge::strays(const std::vector<double>& m, size_t window, double gate)
{
	std::vector<Stretch> out;
	for (size_t a = 0; a < m.size(); a++)
	{
		if (m[a] <= gate) continue;
		if (!out.empty() && a <= out.back().second + window)
			out.back().second = a + window;
		else
			out.emplace_back(a, a + window);
	}
	return out;
}

double OdometryBridge::worst(const std::vector<double>& m)
{
	return m.empty() ? 0 : *std::max_element(m.begin(), m.end());
}

std::vector<OdometryBridge::Stretch> OdometryBridge::candidates(
	const std::vector<Stretch>& strays, size_t margin, size_t n)
{
	std::vector<Stretch> out;
	const auto widened = [&](size_t a, size_t b) {
		out.emplace_back(a > margin ? a - margin : 0, std::min(b + margin, n - 1));
	};
	for (size_t k = 0; k < strays.size(); k++)
	{
		widened(strays[k].first, strays[k].second);
		if (k + 1 < strays.size()) widened(strays[k].first, strays[k + 1].second);
	}
	return out;
}

OdometryBridge::Path OdometryBridge::bridge(const Path& path, const std::vector<OdometryFactor>& odometry, Stretch s)
{
	const auto [a, b] = s;
	Path out = path;
	for (size_t i = a + 1; i <= b; i++) out[i] = odometry[i].end(out[i - 1]);
	Eigen::Vector3d gap = path[b] - out[b];
	gap[2] = core::wrapToPi(gap[2]);
	for (size_t i = a + 1; i <= b; i++)
	{
		out[i] += gap * static_cast<double>(i - a) / static_cast<double>(b - a);
		out[i][2] = core::wrapToPi(out[i][2]);
	}
	return out;
}
}  // namespace whiskermap::smooth
