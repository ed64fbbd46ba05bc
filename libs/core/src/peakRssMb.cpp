#include <sys/resource.h>
#include <whiskermap/core/peakRssMb.h>

namespace whiskermap::core
{
double peakRssMb()
{
	rusage usage{};
	::getrusage(RUSAGE_SELF, &usage);
	return static_cast<double>(usage.ru_maxrss) / 1024.0;
}
}  // namespace whiskermap::core
