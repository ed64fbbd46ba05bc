#pragma once
#include <cstddef>
#include <string>

namespace whiskermap::cli
{
/** whisker-export's range outputs (doc/formats.md, "Whisker sweeps as range rays"): the
 *  sweeps of a rawlog as stock MRPT range rays (obs::WhiskerRanges), for MRPT's own
 *  occupancy grid. The input must have been checked (obs::RawlogReader's constructor). */
struct RangeExport
{
	/** Copies the rawlog `in` to `out` (gzip) object by object, in the same layout: every
	 *  CObservationWhiskerContacts, alone or in a sensory frame, becomes its rays; every other
	 *  object (odometry observations, action collections) is written byte for byte as read.
	 *  Returns the number of sweeps converted. Throws core::Error naming the file. */
	static size_t writeRawlog(const std::string& in, const std::string& out);

	/** Writes a .simplemap of the rays of every sweep of `in` at the rawlog's robot pose of
	 *  that sweep (one entry per sweep; a rawlog with exact odometry gives the true poses).
	 *  Returns the number of entries. */
	static size_t writeSimpleMap(const std::string& in, const std::string& out);
};
}  // namespace whiskermap::cli
