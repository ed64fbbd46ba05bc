#pragma once
#include <Eigen/Core>

namespace whiskermap::inference
{
/** Gradient `g` and Hessian `H` at 0 of f: R^3 -> R by central differences of step `h`, from
 *  9 values of f besides f(0) = `value`: g_i = (f(h e_i) - f(-h e_i)) / 2h,
 *  H_ii = (f(h e_i) - 2 f(0) + f(-h e_i)) / h^2, H_ij = (f(h e_i + h e_j) - f(h e_i) - f(h e_j) + f(0)) / h^2.
 *  Shared by the rigid table fit's Newton steps and its pose spread's proposal. */
template <class F>
void finiteDifferences(const F& f, double value, double h, Eigen::Vector3d& g, Eigen::Matrix3d& H)
{
	Eigen::Vector3d fp, fm;
	for (int i = 0; i < 3; i++)
	{
		const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(i);
		fp[i] = f(e), fm[i] = f(Eigen::Vector3d(-e));
		g[i] = (fp[i] - fm[i]) / (2 * h), H(i, i) = (fp[i] - 2 * value + fm[i]) / (h * h);
	}
	for (int i = 0; i < 3; i++)
		for (int j = i + 1; j < 3; j++)
			H(i, j) = H(j, i) =
				(f(Eigen::Vector3d(h * Eigen::Vector3d::Unit(i) + h * Eigen::Vector3d::Unit(j))) - fp[i] - fp[j] + value) /
				(h * h);
}
}  // namespace whiskermap::inference
