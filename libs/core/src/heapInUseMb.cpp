#include <malloc.h>
#include <whiskermap/core/heapInUseMb.h>

#include <limits>

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define WHISKERMAP_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define WHISKERMAP_ASAN 1
#endif

namespace whiskermap::core
{
double heapInUseMb()
{
#ifdef WHISKERMAP_ASAN
	return std::numeric_limits<double>::quiet_NaN();  // the sanitizer's allocator, not glibc's
#else
	const struct mallinfo2 m = ::mallinfo2();
	return static_cast<double>(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
#endif
}
}  // namespace whiskermap::core
