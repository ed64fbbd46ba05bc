#pragma once
#include <cstddef>
#include <cstdint>
#include <random>

namespace whiskermap::inference
{
/** The sampler's random numbers: one std::mt19937_64; uniforms from its 53 high bits and
 *  Gaussians by Box-Muller from those (no std::*_distribution: the same numbers on every
 *  standard library, doc/sampler.md "Reproducible"). */
class SamplerRandom
{
   public:
	void seed(uint64_t s) { m_rng.seed(s); }
	/** U[0, 1). */
	double uniform() { return static_cast<double>(m_rng() >> 11) * 0x1.0p-53; }
	/** Uniform in {0, ..., n - 1}. */
	size_t pick(size_t n) { return static_cast<size_t>(uniform() * static_cast<double>(n)); }
	/** N(0, 1). */
	double gaussian();

   private:
	std::mt19937_64 m_rng;
};
}  // namespace whiskermap::inference
