#pragma once
#include <Eigen/Core>

#include <functional>
#include <vector>

namespace whiskermap::baseline
{
/** Minimises a sum of squared residuals over three parameters (x, y, yaw of a leg or a
 *  table): Levenberg-Marquardt with a central-difference Jacobian. */
struct LeastSquares
{
	/** Fills `out` with the residuals at `x` (any number, the same at every call). */
	using Residuals = std::function<void(const Eigen::Vector3d& x, std::vector<double>& out)>;

	struct Result
	{
		Eigen::Vector3d x{0, 0, 0};
		double cost = 0;  ///< sum of squared residuals at x
		Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< (J^T J)^-1 at x (pseudo-inverse)
	};

	static Result solve(const Eigen::Vector3d& x0, const Residuals& f, int iterations = 30);

	/** Huber's robust residual: z itself within +-k, growing like sqrt(|z|) beyond, so that
	 *  its square is Huber's loss (2 k |z| - k^2). */
	static double huber(double z, double k = 3.0);
};
}  // namespace whiskermap::baseline
