#pragma once

namespace whiskermap::core
{
/** Memoised std::log, std::sin and std::cos: the inference evaluates a few angles (a leg's
 *  or table's yaw) and constants (log alpha_S, log c_L, ...) millions of times. A small
 *  direct-mapped cache per thread, keyed on the argument's bits, returns exactly what the
 *  std function returns (doc/benchmarks.md, "Lasting map"). */
double cachedLog(double x);

struct SinCos
{
	double sin, cos;
};
SinCos cachedSinCos(double a);
}  // namespace whiskermap::core
