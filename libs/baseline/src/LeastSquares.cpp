#include <whiskermap/baseline/LeastSquares.h>

#include <Eigen/Dense>
#include <cmath>

namespace whiskermap::baseline
{
namespace
{
double sumSq(const std::vector<double>& r)
{
	double s = 0;
	for (double v : r) s += v * v;
	return s;
}

/** Central-difference Jacobian of f at x (residuals r0 at x are only used for the size). */
Eigen::MatrixXd jacobian(const LeastSquares::Residuals& f, const Eigen::Vector3d& x, size_t m)
{
	Eigen::MatrixXd J(m, 3);
	std::vector<double> rp, rm;
	for (int j = 0; j < 3; j++)
	{
		const double h = 1e-6;
		Eigen::Vector3d xp = x, xm = x;
		xp[j] += h, xm[j] -= h;
		f(xp, rp);
		f(xm, rm);
		for (size_t i = 0; i < m; i++) J(i, j) = (rp[i] - rm[i]) / (2 * h);
	}
	return J;
}
}  // namespace

LeastSquares::Result LeastSquares::solve(const Eigen::Vector3d& x0, const Residuals& f, int iterations)
{
	Result res;
	res.x = x0;
	std::vector<double> r;
	f(res.x, r);
	res.cost = sumSq(r);
	double lambda = 1e-3;
	Eigen::MatrixXd J = jacobian(f, res.x, r.size());
	for (int it = 0; it < iterations; it++)
	{
		const Eigen::Map<const Eigen::VectorXd> rv(r.data(), Eigen::Index(r.size()));
		const Eigen::Matrix3d H = J.transpose() * J;
		const Eigen::Vector3d g = J.transpose() * rv;
		Eigen::Matrix3d A = H;
		A.diagonal() += lambda * (H.diagonal().array() + 1e-12).matrix();
		const Eigen::Vector3d step = -A.ldlt().solve(g);
		std::vector<double> rn;
		f(res.x + step, rn);
		const double cost = sumSq(rn);
		if (cost < res.cost)
		{
			res.x += step, res.cost = cost, r = std::move(rn);
			lambda = std::max(lambda / 10, 1e-9);
			J = jacobian(f, res.x, r.size());
			if (step.norm() < 1e-10) break;
		}
		else if ((lambda *= 10) > 1e8)
			break;
	}
	const Eigen::Matrix3d H = J.transpose() * J;
	res.covariance = H.completeOrthogonalDecomposition().pseudoInverse();
	return res;
}

double LeastSquares::huber(double z, double k)
{
	if (std::abs(z) <= k) return z;
	return std::copysign(std::sqrt(2 * k * std::abs(z) - k * k), z);
}
}  // namespace whiskermap::baseline
