#pragma once
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <string>

namespace whiskermap::maps
{
/** Writes an MRPT `.simplemap` (a CSimpleMap: pose + sensory frame per entry) one entry at a
 *  time, so memory stays bounded however many sweeps: the file is byte for byte what
 *  CSimpleMap::saveToFile would write for the same entries. The number of entries must be
 *  known up front (the format stores it first); close() checks it was met. */
class SimpleMapWriter
{
   public:
	/** Throws core::Error if `path` cannot be created. */
	SimpleMapWriter(const std::string& path, uint32_t entries);
	/** One entry: the robot pose (as a 3-D Gaussian with zero covariance) and a sensory
	 *  frame holding `obs`. */
	void add(const mrpt::poses::CPose2D& pose, const mrpt::obs::CObservation::Ptr& obs);
	/** One entry holding a whole sensory frame. */
	void add(const mrpt::poses::CPose2D& pose, const mrpt::obs::CSensoryFrame& frame);
	/** Ends the file; throws core::Error if fewer or more entries were added than announced. */
	void close();

   private:
	std::string m_path;
	mrpt::io::CFileGZOutputStream m_out;
	uint32_t m_expected, m_written = 0;
};
}  // namespace whiskermap::maps
