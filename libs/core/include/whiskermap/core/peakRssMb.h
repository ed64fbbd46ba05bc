#pragma once

namespace whiskermap::core
{
/** The process's peak resident memory so far (getrusage's ru_maxrss), in MB. */
double peakRssMb();
}  // namespace whiskermap::core
