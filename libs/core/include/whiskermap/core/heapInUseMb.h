#pragma once

namespace whiskermap::core
{
/** The bytes malloc holds for live allocations now (glibc's mallinfo2: uordblks plus the
 *  mmapped blocks), in MB. Beside peakRssMb() it tells live data from the allocator's free
 *  but unreturned memory. NaN in a build with AddressSanitizer, whose allocator glibc's
 *  figures do not see. */
double heapInUseMb();
}  // namespace whiskermap::core
