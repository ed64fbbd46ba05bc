#pragma once
#include <Eigen/Core>

#include <vector>

namespace whiskermap::eval
{
/** The OSPA metric between two finite point sets (Schuhmacher, Vo & Vo, "A Consistent Metric
 *  for Performance Evaluation of Multi-Object Filters", IEEE TSP 2008), with cut-off c and
 *  order p. For |X| = m <= n = |Y|:
 *    OSPA = ( (1/n) (min over assignments sum_i min(c, |x_i - y_pi(i)|)^p + c^p (n - m)) )^(1/p),
 *  0 when both are empty, c when exactly one is. Symmetric; in [0, c]. */
struct Ospa
{
	static double distance(
		const std::vector<Eigen::Vector2d>& X, const std::vector<Eigen::Vector2d>& Y, double c,
		double p);
};
}  // namespace whiskermap::eval
