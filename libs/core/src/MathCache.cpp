#include <whiskermap/core/MathCache.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace whiskermap::core
{
namespace
{
constexpr int BITS = 6;  // 64 entries per cache and thread
/** A NaN no arithmetic produces: marks an empty entry (its value is NaN too, as for any NaN). */
constexpr uint64_t EMPTY = 0x7ff8dead0000beefull;

uint64_t bitsOf(double x)
{
	uint64_t b = 0;
	std::memcpy(&b, &x, sizeof b);
	return b;
}

size_t slot(uint64_t bits) { return static_cast<size_t>((bits * 0x9E3779B97F4A7C15ull) >> (64 - BITS)); }

template <class V>
struct Cache
{
	struct Entry
	{
		uint64_t key = EMPTY;
		V value;
	};
	Entry entries[1 << BITS];
};
}  // namespace

double cachedLog(double x)
{
	constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
	static thread_local Cache<double> cache = [] {
		Cache<double> c;
		for (auto& e : c.entries) e.value = NaN;
		return c;
	}();
	const uint64_t b = bitsOf(x);
	auto& e = cache.entries[slot(b)];
	if (e.key != b) e.key = b, e.value = std::log(x);
	return e.value;
}

SinCos cachedSinCos(double a)
{
	constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
	static thread_local Cache<SinCos> cache = [] {
		Cache<SinCos> c;
		for (auto& e : c.entries) e.value = {NaN, NaN};
		return c;
	}();
	const uint64_t b = bitsOf(a);
	auto& e = cache.entries[slot(b)];
	if (e.key != b) e.key = b, e.value = {std::sin(a), std::cos(a)};
	return e.value;
}
}  // namespace whiskermap::core
