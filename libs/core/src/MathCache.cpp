#include <whiskermap/core/MathCache.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>

// Process-wide tables of lock-free atomics, not thread_local ones: a thread-local access from
// a shared library is a call (__tls_get_addr) that costs about what the cache saves.
namespace whiskermap::core
{
namespace
{
uint64_t bitsOf(double x)
{
	uint64_t b = 0;
	std::memcpy(&b, &x, sizeof b);
	return b;
}

double valueOf(uint64_t b)
{
	double x = 0;
	std::memcpy(&x, &b, sizeof x);
	return x;
}

constexpr size_t SLOTS = 64;
size_t slot(uint64_t bits) { return static_cast<size_t>((bits * 0x9E3779B97F4A7C15ull) >> 58); }

/** Logarithms: arguments are model constants (a handful per process), so each slot is
 *  written once (claimed by one thread, then published) and never replaced; a full table
 *  or a slot being written falls back to std::log. */
constexpr uint64_t FREE = 0, BUSY = 1;  // the bits of +0.0 and of a subnormal: logged directly
struct LogSlot
{
	std::atomic<uint64_t> key{FREE};
	std::atomic<uint64_t> value{0};
};
LogSlot logSlots[SLOTS];

/** Sines and cosines: angles change all the time, so slots are replaced; a sequence number
 *  per slot (odd while being written) tells a reader that its copy is whole (a seqlock).
 *  Empty slots hold a NaN no arithmetic produces (not 0: that is the key of angle +0). */
constexpr uint64_t NO_ANGLE = 0x7ff8dead0000beefull;
struct AngleSlot
{
	std::atomic<uint64_t> sequence{0}, key{NO_ANGLE}, sin{0}, cos{0};
};
AngleSlot angleSlots[SLOTS];
}  // namespace

double cachedLog(double x)
{
	const uint64_t b = bitsOf(x);
	if (b == FREE || b == BUSY) return std::log(x);
	for (size_t i = slot(b), probe = 0; probe < SLOTS; probe++, i = (i + 1) % SLOTS)
	{
		LogSlot& s = logSlots[i];
		uint64_t k = s.key.load(std::memory_order_acquire);
		if (k == b) return valueOf(s.value.load(std::memory_order_relaxed));
		if (k == BUSY) break;
		if (k != FREE) continue;
		if (!s.key.compare_exchange_strong(k, BUSY, std::memory_order_acquire)) break;
		const double v = std::log(x);
		s.value.store(bitsOf(v), std::memory_order_relaxed);
		s.key.store(b, std::memory_order_release);
		return v;
	}
	return std::log(x);
}

SinCos cachedSinCos(double a)
{
	const uint64_t b = bitsOf(a);
	if (b == NO_ANGLE) return {std::sin(a), std::cos(a)};
	AngleSlot& s = angleSlots[slot(b)];
	const uint64_t seq = s.sequence.load(std::memory_order_acquire);
	if (seq % 2 == 0 && s.key.load(std::memory_order_relaxed) == b)
	{
		const SinCos hit{valueOf(s.sin.load(std::memory_order_relaxed)), valueOf(s.cos.load(std::memory_order_relaxed))};
		std::atomic_thread_fence(std::memory_order_acquire);
		if (s.sequence.load(std::memory_order_relaxed) == seq) return hit;
	}
	const SinCos v{std::sin(a), std::cos(a)};
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
}  // namespace whiskermap::core
