// Fuzz target: CObservationWhiskerContacts deserialized by MRPT's own ReadObject, as stock
// tools given our plugin read it (no RawlogScanner in front). The input is the payload
// after the class header and version byte, which the target supplies.
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <cstring>
#include <vector>

using whiskermap::obs::CObservationWhiskerContacts;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const char name[] = "whiskermap::obs::CObservationWhiskerContacts";
	constexpr size_t n = sizeof(name) - 1;
	std::vector<uint8_t> bytes(n + 2 + size);
	bytes[0] = static_cast<uint8_t>(0x80 | n);
	std::memcpy(&bytes[1], name, n);
	bytes[n + 1] = 0;  // version
	if (size) std::memcpy(&bytes[n + 2], data, size);
	mrpt::io::CMemoryStream m;
	m.assignMemoryNotOwn(bytes.data(), bytes.size());
	auto arch = mrpt::serialization::archiveFrom(m);
	try
	{
		CObservationWhiskerContacts o;
		arch.ReadObject(&o);
		o.toShapelets(mrpt::poses::CPose2D(1, 2, 0.5));
		o.validate();
	}
	catch (const std::exception&)
	{
	}
	return 0;
}
