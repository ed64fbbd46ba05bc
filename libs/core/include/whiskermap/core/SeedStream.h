#pragma once
#include <cstdint>

namespace whiskermap::core
{
/** Independent random streams from one user seed: the 32-bit seed of stream `stream`
 *  (splitmix64 of seed and stream). A run draws its sensor noise, odometry noise and
 *  trajectory from different streams, so changing one never shifts the others. */
constexpr uint32_t seedStream(uint64_t seed, uint64_t stream)
{
	uint64_t x = seed ^ (stream * 0xD1B54A32D192ED03ull);
	x += 0x9E3779B97F4A7C15ull;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
	x ^= x >> 31;
	return static_cast<uint32_t>(x ^ (x >> 32));
}
}  // namespace whiskermap::core
