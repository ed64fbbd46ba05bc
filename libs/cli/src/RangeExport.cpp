#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/cli/RangeExport.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/SimpleMapWriter.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/obs/RawlogScanner.h>
#include <whiskermap/obs/WhiskerRanges.h>

namespace whiskermap::cli
{
namespace
{
/** The object stored in `bytes` (already checked by RawlogScanner). */
mrpt::serialization::CSerializable::Ptr deserialize(const std::vector<uint8_t>& bytes)
{
	mrpt::io::CMemoryStream m;
	m.assignMemoryNotOwn(bytes.data(), bytes.size());
	return mrpt::serialization::archiveFrom(m).ReadObject();
}

/** `frame` with each whisker sweep replaced by its rays; other observations kept. */
mrpt::obs::CSensoryFrame toRays(const mrpt::obs::CSensoryFrame& frame, size_t& sweeps)
{
	mrpt::obs::CSensoryFrame out;
	for (const auto& o : frame)
	{
		if (const auto* s = dynamic_cast<const obs::CObservationWhiskerContacts*>(o.get()))
		{
			for (const auto& ray : obs::WhiskerRanges::fromSweep(*s)) out.insert(ray);
			sweeps++;
		}
		else
			out.insert(o);
	}
	return out;
}
}  // namespace

size_t RangeExport::writeRawlog(const std::string& in, const std::string& out)
{
	auto src = obs::ByteSource::file(in);
	obs::RawlogScanner scan(*src, in);
	mrpt::io::CFileGZOutputStream f;
	if (!f.open(out)) throw core::Error(out + ": cannot create file");
	auto arch = mrpt::serialization::archiveFrom(f);
	obs::RawlogScanner::Object o;
	size_t sweeps = 0;
	while (scan.next(o))
	{
		if (o.className == "whiskermap::obs::CObservationWhiskerContacts")
		{
			const auto sweep = std::dynamic_pointer_cast<obs::CObservationWhiskerContacts>(deserialize(o.bytes));
			for (const auto& ray : obs::WhiskerRanges::fromSweep(*sweep)) arch << *ray;
			sweeps++;
		}
		else if (o.className == "mrpt::obs::CSensoryFrame")
			arch << toRays(*std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(deserialize(o.bytes)), sweeps);
		else
			f.Write(o.bytes.data(), o.bytes.size());  // odometry, actions: as read
	}
	f.close();
	return sweeps;
}

size_t RangeExport::writeSimpleMap(const std::string& in, const std::string& out)
{
	obs::RawlogReader reader(in);
	maps::SimpleMapWriter w(out, static_cast<uint32_t>(reader.summary().sweepCount));
	obs::RawlogReader::Sweep s;
	while (reader.next(s))
	{
		mrpt::obs::CSensoryFrame sf;
		for (const auto& ray : obs::WhiskerRanges::fromSweep(*s.obs)) sf.insert(ray);
		w.add(s.robotPose, sf);
	}
	w.close();
	return reader.summary().sweepCount;
}
}  // namespace whiskermap::cli
