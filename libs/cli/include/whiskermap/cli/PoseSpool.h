#pragma once
#include <mrpt/math/TPose2D.h>

#include <cstdio>

namespace whiskermap::cli
{
/** Timestamped poses kept on disk, not in memory: an anonymous temporary file (std::tmpfile,
 *  gone when closed and, on POSIX, when the process dies), exact doubles, read back in the
 *  order written. A path of any length in constant memory, bit for bit. */
class PoseSpool
{
   public:
	PoseSpool();  ///< throws core::Error when no temporary file can be made
	~PoseSpool();
	PoseSpool(const PoseSpool&) = delete;
	PoseSpool& operator=(const PoseSpool&) = delete;

	void write(double t, const mrpt::math::TPose2D& pose);  ///< throws core::Error (disk full)
	/** Back to the first pose; next() then returns the poses in the order written. */
	void rewind();
	bool next(double& t, mrpt::math::TPose2D& pose);  ///< false after the last one
	size_t size() const { return m_count; }

   private:
	std::FILE* m_file = nullptr;
	size_t m_count = 0;
};
}  // namespace whiskermap::cli
