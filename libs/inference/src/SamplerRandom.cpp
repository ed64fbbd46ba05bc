#include <whiskermap/inference/SamplerRandom.h>

#include <cmath>

namespace whiskermap::inference
{
// Box-Muller from our own uniforms: the same numbers on every standard library.
double SamplerRandom::gaussian()
{
	const double u1 = 1.0 - uniform(), u2 = uniform();
	return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
}
}  // namespace whiskermap::inference
