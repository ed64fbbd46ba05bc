// Fuzz target: the rawlog reader (RawlogScanner + RawlogReader) on a raw byte stream.
// Bad input may only be refused with core::Error; anything else is a finding.
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/RawlogReader.h>

using namespace whiskermap;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	try
	{
		obs::RawlogReader r([&] { return obs::ByteSource::memory(data, size); }, "fuzz.rawlog");
		obs::RawlogReader::Sweep s;
		while (r.next(s)) s.obs->toShapelets(s.robotPose);
	}
	catch (const core::Error&)
	{
	}
	return 0;
}
