#include <whiskermap/core/MathCache.h>

#include <cmath>

// Process-wide tables of lock-free atomics, not thread_local ones: a thread-local access from
// a shared library is a call (__tls_get_addr) that costs about what the cache saves. The
// header reads them inline; the misses below write them.
namespace whiskermap::core::detail
{
/** Logarithms: arguments are model constants (a handful per process), so each slot is
 *  written once (claimed by one thread, then published) and never replaced; a full table
 *  or a slot being written falls back to std::log. */
LogSlot logSlots[CACHE_SLOTS];

/** Sines and cosines: angles change all the time, so slots are replaced; a sequence number
 *  per slot (odd while being written) tells a reader that its copy is whole (a seqlock). */
AngleSlot angleSlots[CACHE_SLOTS];

double cachedLogMiss(double x)
{
	const uint64_t b = bitsOf(x);
	if (b == LOG_FREE || b == LOG_BUSY) return std::log(x);
	for (size_t i = cacheSlot(b), probe = 0; probe < CACHE_SLOTS; probe++, i = (i + 1) % CACHE_SLOTS)
	{
		LogSlot& s = logSlots[i];
		uint64_t k = s.key.load(std::memory_order_acquire);
		if (k == b) return valueOf(s.value.load(std::memory_order_relaxed));
		if (k == LOG_BUSY) break;
		if (k != LOG_FREE) continue;
		if (!s.key.compare_exchange_strong(k, LOG_BUSY, std::memory_order_acquire)) break;
		const double v = std::log(x);
		s.value.store(bitsOf(v), std::memory_order_relaxed);
		s.key.store(b, std::memory_order_release);
		return v;
	}
	return std::log(x);
}

SinCos cachedSinCosMiss(double a)
{
	const uint64_t b = bitsOf(a);
	const SinCos v{std::sin(a), std::cos(a)};
	if (b == NO_ANGLE) return v;
	AngleSlot& s = angleSlots[cacheSlot(b)];
	const uint64_t seq = s.sequence.load(std::memory_order_acquire);
	uint64_t expected = seq;
	if (seq % 2 == 0 && s.sequence.compare_exchange_strong(expected, seq + 1, std::memory_order_relaxed))
	{
		std::atomic_thread_fence(std::memory_order_release);  // the odd number before the data
		s.key.store(b, std::memory_order_relaxed);
		s.sin.store(bitsOf(v.sin), std::memory_order_relaxed);
		s.cos.store(bitsOf(v.cos), std::memory_order_relaxed);
		s.sequence.store(seq + 2, std::memory_order_release);
	}
	return v;
}
}  // namespace whiskermap::core::detail
