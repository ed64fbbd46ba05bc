#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/conciseMessage.h>
#include <whiskermap/obs/RawlogReader.h>
#include <zlib.h>

#include <array>
#include <filesystem>
#include <optional>

using namespace whiskermap::obs;
using whiskermap::core::Error;

namespace
{
/** Decompresses a whole gzip file once to catch truncation or corruption, which the
 *  object reader could otherwise take for a clean end of file. */
void checkGzipIntegrity(const std::string& path)
{
	std::array<unsigned char, 2> magic{};
	{
		FILE* f = std::fopen(path.c_str(), "rb");
		if (!f) throw Error(path + ": cannot open file");
		const size_t n = std::fread(magic.data(), 1, 2, f);
		std::fclose(f);
		if (n == 0) throw Error(path + ": empty file, not a rawlog");
		if (n < 2 || magic[0] != 0x1f || magic[1] != 0x8b) return;  // plain, uncompressed
	}
	gzFile g = gzopen(path.c_str(), "rb");
	if (!g) throw Error(path + ": cannot open file");
	std::array<char, 1 << 16> buf{};
	int got = 0;
	while ((got = gzread(g, buf.data(), buf.size())) > 0)
	{
	}
	int err = Z_OK;
	std::string msg = gzerror(g, &err);
	gzclose(g);
	if (msg.rfind(path + ": ", 0) == 0) msg = msg.substr(path.size() + 2);
	if (got < 0 || err != Z_OK)
		throw Error(path + ": truncated or corrupt gzip data (" + msg + ")");
}
}  // namespace

RawlogReader::Contents RawlogReader::read(const std::string& path)
{
	std::vector<Sweep> sweeps;
	auto c = forEach(path, [&](const Sweep& s) { sweeps.push_back(s); });
	c.sweeps = std::move(sweeps);
	return c;
}

RawlogReader::Contents RawlogReader::forEach(
	const std::string& path, const std::function<void(const Sweep&)>& onSweep)
{
	if (!std::filesystem::exists(path)) throw Error(path + ": no such file");
	if (std::filesystem::is_directory(path)) throw Error(path + ": is a directory, not a rawlog");
	checkGzipIntegrity(path);

	mrpt::io::CFileGZInputStream f;
	if (!f.open(path)) throw Error(path + ": cannot open file");
	auto arch = mrpt::serialization::archiveFrom(f);

	Contents c;
	std::optional<mrpt::poses::CPose2D> pose;
	auto addSweep = [&](const mrpt::obs::CObservation::Ptr& o) {
		auto w = std::dynamic_pointer_cast<CObservationWhiskerContacts>(o);
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o))
			pose = odo->odometry;
		if (!w) return;
		if (!pose)
			throw Error(
				path + ": whisker sweep at object #" + std::to_string(c.objects) +
				" has no robot pose before it (no odometry or action)");
		c.sweepCount++;
		onSweep(Sweep{*pose, w});
	};

	for (;;)
	{
		mrpt::serialization::CSerializable::Ptr obj;
		try
		{
			obj = arch.ReadObject();
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			break;
		}
		catch (const std::exception& e)
		{
			throw Error(
				path + ": corrupt rawlog at object #" + std::to_string(c.objects) + ": " +
				core::conciseMessage(e));
		}
		if (auto acts = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
		{
			c.actionSensoryFrameFormat = true;
			if (auto mv = acts->getBestMovementEstimation())
				pose = (pose ? *pose : mrpt::poses::CPose2D()) + mv->poseChange->getMeanVal();
		}
		else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
		{
			for (const auto& o : *sf) addSweep(o);
		}
		else if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj))
		{
			addSweep(o);
		}
		else
		{
			throw Error(
				path + ": object #" + std::to_string(c.objects) + " has class " +
				obj->GetRuntimeClass()->className + ", which does not belong in a rawlog");
		}
		c.objects++;
	}
	if (c.objects == 0) throw Error(path + ": holds no objects, not a rawlog");
	return c;
}
