#include <whiskermap/core/Error.h>
#include <whiskermap/eval/Hungarian.h>
#include <whiskermap/eval/Ospa.h>

#include <cmath>

namespace whiskermap::eval
{
double Ospa::distance(
	const std::vector<Eigen::Vector2d>& X, const std::vector<Eigen::Vector2d>& Y, double c,
	double p)
{
	if (!(c > 0) || !(p >= 1)) throw core::Error("OSPA: need cut-off c > 0 and order p >= 1");
	const auto& small = X.size() <= Y.size() ? X : Y;
	const auto& large = X.size() <= Y.size() ? Y : X;
	if (large.empty()) return 0;
	if (small.empty()) return c;
	Eigen::MatrixXd cost(small.size(), large.size());
	for (size_t i = 0; i < small.size(); i++)
		for (size_t j = 0; j < large.size(); j++)
			cost(i, j) = std::pow(std::min(c, (small[i] - large[j]).norm()), p);
	const auto assignment = Hungarian::solve(cost);
	double sum = std::pow(c, p) * double(large.size() - small.size());
	for (size_t i = 0; i < small.size(); i++) sum += cost(i, assignment[i]);
	return std::pow(sum / double(large.size()), 1 / p);
}
}  // namespace whiskermap::eval
