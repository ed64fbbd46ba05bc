#include <malloc.h>
#include <whiskermap/core/heapInUseMb.h>

namespace whiskermap::core
{
double heapInUseMb()
{
	const struct mallinfo2 m = ::mallinfo2();
	return static_cast<double>(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
}
}  // namespace whiskermap::core
