#pragma once
#include <mrpt/poses/CPose2D.h>
#include <whiskermap/obs/ByteSource.h>

#include <cstdint>
#include <string>
#include <vector>

namespace whiskermap::obs
{
/** Splits a rawlog byte stream into its top-level objects and checks every byte of each
 *  against the layouts MRPT 2.5.8 writes, before any deserializer sees it: class names
 *  from a fixed list, known serialization versions, every length and count bounded before
 *  anything is allocated, bools 0 or 1, every number finite and within the bounds of
 *  doc/formats.md ("What the reader checks"), the end-of-object flag, and an end of file
 *  inside an object is an error. Memory: one object (at most MAX_OBJECT_BYTES).
 *
 *  Classes read: CObservationOdometry, CObservationWhiskerContacts, CSensoryFrame holding
 *  those, CActionCollection holding CActionRobotMovement2D (odometry estimate, Gaussian or
 *  Thrun model). Anything else is refused. */
class RawlogScanner
{
   public:
	static constexpr size_t MAX_OBJECT_BYTES = 8u << 20;
	/** Robot positions and pose increments beyond this (metres) are refused. */
	static constexpr double MAX_COORDINATE = 1e5;

	/** What one top-level object says, in order. */
	struct Item
	{
		enum Kind
		{
			AbsolutePose,  ///< a CObservationOdometry: `pose` is where the robot is
			Increment,  ///< the first CActionRobotMovement2D of a collection: `pose` is the move
			Sweep  ///< a CObservationWhiskerContacts: bytes [offset, offset + size) of the object
		} kind;
		mrpt::poses::CPose2D pose;
		size_t offset = 0, size = 0;
	};
	struct Object
	{
		std::string className;
		std::vector<uint8_t> bytes;  ///< the object as stored
		std::vector<Item> items;
	};

	/** `label` (the file) starts every error message. */
	RawlogScanner(ByteSource& in, std::string label);

	/** The next object; false at a clean end of the data. Throws core::Error, one line:
	 *  "<label>: corrupt rawlog at object #N: <Class>: <problem>". */
	bool next(Object& out);
	/** Objects read so far. */
	size_t objects() const { return m_objects; }

   private:
	ByteSource& m_in;
	std::string m_label;
	size_t m_objects = 0;
};
}  // namespace whiskermap::obs
