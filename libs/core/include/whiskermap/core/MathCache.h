#pragma once
#include <atomic>
#include <cstdint>
#include <cstring>

namespace whiskermap::core
{
/** Memoised std::log, std::sin and std::cos: the inference evaluates a few angles (a leg's
 *  or table's yaw) and constants (log alpha_S, log c_L, ...) millions of times. Small
 *  process-wide tables keyed on the argument's bits return exactly what the std function
 *  returns (doc/benchmarks.md, "Lasting map"). The lookup of a cached value is inline (a
 *  call into this library costs about what the lookup does); a miss goes out of line. */
struct SinCos
{
	double sin, cos;
};

namespace detail
{
/** The tables behind cachedLog and cachedSinCos (MathCache.cpp says how they are written). */
constexpr size_t CACHE_SLOTS = 64;
inline uint64_t bitsOf(double x)
{
	uint64_t b = 0;
	std::memcpy(&b, &x, sizeof b);
	return b;
}
inline double valueOf(uint64_t b)
{
	double x = 0;
	std::memcpy(&x, &b, sizeof x);
	return x;
}
inline size_t cacheSlot(uint64_t bits) { return static_cast<size_t>((bits * 0x9E3779B97F4A7C15ull) >> 58); }

constexpr uint64_t LOG_FREE = 0, LOG_BUSY = 1;  ///< keys of slots not holding a value (the bits of +0.0 and a subnormal)
constexpr uint64_t NO_ANGLE = 0x7ff8dead0000beefull;  ///< the key of an empty angle slot: a NaN no arithmetic produces
struct LogSlot
{
	std::atomic<uint64_t> key{LOG_FREE};
	std::atomic<uint64_t> value{0};
};
struct AngleSlot
{
	std::atomic<uint64_t> sequence{0}, key{NO_ANGLE}, sin{0}, cos{0};
};
extern LogSlot logSlots[CACHE_SLOTS];
extern AngleSlot angleSlots[CACHE_SLOTS];
double cachedLogMiss(double x);
SinCos cachedSinCosMiss(double a);
}  // namespace detail

/** std::log(x), exactly. The first probe is inline: a model constant nearly always sits in its own slot. */
inline double cachedLog(double x)
{
	const uint64_t b = detail::bitsOf(x);
	const detail::LogSlot& s = detail::logSlots[detail::cacheSlot(b)];
	if (b != detail::LOG_FREE && b != detail::LOG_BUSY && s.key.load(std::memory_order_acquire) == b)
		return detail::valueOf(s.value.load(std::memory_order_relaxed));
	return detail::cachedLogMiss(x);
}

/** {std::sin(a), std::cos(a)}, exactly; the lookup is inline, a miss computes and caches. */
inline SinCos cachedSinCos(double a)
{
	const uint64_t b = detail::bitsOf(a);
	const detail::AngleSlot& s = detail::angleSlots[detail::cacheSlot(b)];
	const uint64_t seq = s.sequence.load(std::memory_order_acquire);
	if (b != detail::NO_ANGLE && seq % 2 == 0 && s.key.load(std::memory_order_relaxed) == b)
	{
		const SinCos hit{
			detail::valueOf(s.sin.load(std::memory_order_relaxed)), detail::valueOf(s.cos.load(std::memory_order_relaxed))};
		std::atomic_thread_fence(std::memory_order_acquire);
		if (s.sequence.load(std::memory_order_relaxed) == seq) return hit;
	}
	return detail::cachedSinCosMiss(a);
}
}  // namespace whiskermap::core
