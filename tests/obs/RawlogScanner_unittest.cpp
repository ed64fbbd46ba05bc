// Regression tests of issue 8: rawlogs that crashed, hung, exhausted memory or were read
// partly with exit 0. Each file is a plain (uncompressed) MRPT archive made byte by byte;
// every one must be refused with one line naming the file and the object.
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/RawlogReader.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace whiskermap;
using Bytes = std::vector<uint8_t>;

namespace
{
Bytes bytesOf(const mrpt::serialization::CSerializable& o)
{
	mrpt::io::CMemoryStream m;
	mrpt::serialization::archiveFrom(m) << o;
	const auto* p = static_cast<const uint8_t*>(m.getRawBufferData());
	return Bytes(p, p + m.getTotalBytesCount());
}

Bytes odometry(double x, double y, double phi)
{
	mrpt::obs::CObservationOdometry odo;
	odo.sensorLabel = "ODOMETRY";
	odo.odometry = mrpt::poses::CPose2D(x, y, 0);
	auto b = bytesOf(odo);
	// CPose2D's constructor wraps phi, so the raw doubles are patched in: x at offset
	// 1 + 31 + 1 (odometry header) + 1 + 20 + 1 (pose header).
	const size_t at = 2 + std::strlen("mrpt::obs::CObservationOdometry") + 2 + std::strlen("mrpt::poses::CPose2D");
	std::memcpy(&b[at], &x, 8), std::memcpy(&b[at + 8], &y, 8), std::memcpy(&b[at + 16], &phi, 8);
	return b;
}

obs::CObservationWhiskerContacts sweep()
{
	obs::CObservationWhiskerContacts o;
	o.sensorLabel = "WHISKERS";
	obs::TWhisker w;
	w.sweep_start = 1, w.sweep_end = 0, w.length = 0.5, w.touched = true, w.angle = 0.5, w.r = 0.2, w.texture = 0.4;
	o.whiskers = {w, w};
	return o;
}

/** Offset of the first whisker's fields in a serialized sweep (after the header, timestamp,
 *  label, sensor pose object, three std-devs and the count). */
size_t whiskerOffset(const Bytes& b)
{
	const size_t header = 2 + std::strlen("whiskermap::obs::CObservationWhiskerContacts");
	const size_t pose = 2 + std::strlen("mrpt::poses::CPose3D") + 96 + 1;
	(void)b;
	return header + 8 + 4 + std::strlen("WHISKERS") + pose + 24 + 4;
}

class RawlogScannerTest : public ::testing::Test
{
   protected:
	std::string write(const std::vector<Bytes>& objects)
	{
		const auto path = (std::filesystem::temp_directory_path() /
						   ("whiskermap_scan_" + std::to_string(::getpid()) + "_" + std::to_string(n++) + ".rawlog"))
							  .string();
		std::ofstream f(path, std::ios::binary);
		for (const auto& o : objects) f.write(reinterpret_cast<const char*>(o.data()), static_cast<std::streamsize>(o.size()));
		files.push_back(path);
		return path;
	}
	/** The error reading `objects`, or "" when they read fine. */
	std::string error(const std::vector<Bytes>& objects)
	{
		const auto path = write(objects);
		try
		{
			obs::RawlogReader::read(path);
		}
		catch (const core::Error& e)
		{
			const std::string m = e.what();
			EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
			EXPECT_EQ(m.find('\n'), std::string::npos) << m;
			return m;
		}
		return "";
	}
	void TearDown() override
	{
		for (const auto& f : files) std::filesystem::remove(f);
	}
	std::vector<std::string> files;
	int n = 0;
};
}  // namespace

TEST_F(RawlogScannerTest, AGoodLogReads)
{
	EXPECT_EQ(error({odometry(1, 2, 0.5), bytesOf(sweep()), odometry(3, 4, 0), bytesOf(sweep())}), "");
	const auto c = obs::RawlogReader::read(write({odometry(1, 2, 0.5), bytesOf(sweep())}));
	ASSERT_EQ(c.sweeps.size(), 1u);
	EXPECT_DOUBLE_EQ(c.sweeps[0].robotPose.x(), 1);
	EXPECT_DOUBLE_EQ(c.sweeps[0].robotPose.phi(), 0.5);
}

TEST_F(RawlogScannerTest, ANullObjectIsRefused)  // segfaulted every app
{
	const Bytes null = {0x87, 'n', 'u', 'l', 'l', 'p', 't', 'r', 0x88};
	EXPECT_NE(error({null}).find("object #0: a null object"), std::string::npos);
	EXPECT_NE(error({odometry(0, 0, 0), null}).find("object #1: a null object"), std::string::npos);
}

TEST_F(RawlogScannerTest, ACorruptLengthHalfWayIsAnErrorNotAShortLog)  // was exit 0 with half the sweeps
{
	std::vector<Bytes> log;
	for (int i = 0; i < 40; i++) log.push_back(odometry(i, 0, 0)), log.push_back(bytesOf(sweep()));
	// The sensor label's length field of sweep 20 (object #41), after header and timestamp.
	Bytes& b = log[41];
	const uint32_t huge = 0x7fffff00;
	std::memcpy(&b[2 + std::strlen("whiskermap::obs::CObservationWhiskerContacts") + 8], &huge, 4);
	const auto e = error(log);
	EXPECT_NE(e.find("object #41"), std::string::npos) << e;
	EXPECT_NE(e.find("sensor label length: 2147483392 is not in [0, 256]"), std::string::npos) << e;
}

TEST_F(RawlogScannerTest, AnEndOfFileInsideAnObjectIsAnError)
{
	auto b = bytesOf(sweep());
	b.resize(b.size() - 5);
	EXPECT_NE(error({odometry(0, 0, 0), b}).find("truncated file"), std::string::npos);
}

TEST_F(RawlogScannerTest, AnInvalidBoolByteIsRefused)  // loaded as an invalid bool (UB)
{
	auto b = bytesOf(sweep());
	b[whiskerOffset(b) + 5 * 8] = 7;  // whisker 0 `touched`
	EXPECT_NE(error({odometry(0, 0, 0), b}).find("bool byte 7 is not 0 or 1"), std::string::npos);
}

TEST_F(RawlogScannerTest, NonFiniteAndFarPosesAreRefused)  // hung the spatial code or were accepted
{
	for (const double v : {double(NAN), double(INFINITY), 1e300, 2.1e9, 4.3e8, 1e15, -1e6})
	{
		const auto e = error({odometry(v, 0, 0), bytesOf(sweep())});
		EXPECT_NE(e.find("object #0: odometry x"), std::string::npos) << v << ": " << e;
	}
	EXPECT_NE(error({odometry(0, 0, NAN), bytesOf(sweep())}).find("odometry phi: non-finite"), std::string::npos);
	EXPECT_EQ(error({odometry(-99999, 99999, 3), bytesOf(sweep())}), "");
}

TEST_F(RawlogScannerTest, CorruptMotionModelsAreRefusedBeforeMrptSeesThem)  // segfaults and spins in MRPT
{
	mrpt::obs::CActionRobotMovement2D mv;
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions opts;
	mv.computeFromOdometry(mrpt::poses::CPose2D(0.1, 0, 0), opts);
	mrpt::obs::CActionCollection acts;
	acts.insert(mv);
	mrpt::obs::CSensoryFrame sf;
	sf.insert(std::make_shared<obs::CObservationWhiskerContacts>(sweep()));
	const Bytes good = bytesOf(acts), frame = bytesOf(sf);
	EXPECT_EQ(error({good, frame}), "");
	// Offsets in the collection: header, count, movement header, method, raw odometry pose.
	const size_t mvAt = 2 + std::strlen("mrpt::obs::CActionCollection") + 4;
	const size_t modelAt = mvAt + 2 + std::strlen("mrpt::obs::CActionRobotMovement2D") + 4 + 2 +
						   std::strlen("mrpt::poses::CPose2D") + 24 + 1;
	auto thrun = good;
	const uint32_t one = 1, manyParticles = 4000000000u;
	std::memcpy(&thrun[modelAt], &one, 4);
	std::memcpy(&thrun[modelAt + 4 + 24], &manyParticles, 4);
	EXPECT_NE(error({thrun, frame}).find("Thrun model particle count: 4000000000"), std::string::npos);
	auto count = good;
	const uint32_t manyActions = 0xfffffff0u;
	std::memcpy(&count[mvAt - 4], &manyActions, 4);
	EXPECT_NE(error({count, frame}).find("action count: 4294967280"), std::string::npos);
	auto method = good;
	method[mvAt + 2 + std::strlen("mrpt::obs::CActionRobotMovement2D")] = 1;  // a stored PDF
	EXPECT_NE(error({method, frame}).find("estimation method 1"), std::string::npos);
	auto nanStd = good;
	const float nan = NAN;
	std::memcpy(&nanStd[modelAt + 4], &nan, 4);
	EXPECT_NE(error({nanStd, frame}).find("Gaussian model parameter: non-finite"), std::string::npos);
}

TEST_F(RawlogScannerTest, OtherClassesAndOldHeadersAreRefusedBeforeDeserializing)
{
	EXPECT_NE(error({bytesOf(mrpt::poses::CPose2D(1, 2, 0))}).find("class mrpt::poses::CPose2D, which whiskermap does not read"),
			  std::string::npos);
	EXPECT_NE(error({{0x05, 0, 0, 0, 'a'}}).find("not an MRPT object header"), std::string::npos);
	EXPECT_NE(error({{0x80 | 121}}).find("class name length 121"), std::string::npos);
	EXPECT_NE(error({{0x83, 'a', '\n', 'b', 0}}).find("class name holds a byte"), std::string::npos);
}

TEST_F(RawlogScannerTest, TheSummaryIsKnownBeforeTheFirstSweep)
{
	obs::RawlogReader r(write({odometry(1, -2, 0), bytesOf(sweep()), odometry(5, 3, 0), bytesOf(sweep())}));
	EXPECT_EQ(r.summary().sweepCount, 2u);
	EXPECT_EQ(r.summary().objects, 4u);
	EXPECT_DOUBLE_EQ(r.summary().x0, 1);
	EXPECT_DOUBLE_EQ(r.summary().x1, 5);
	EXPECT_DOUBLE_EQ(r.summary().y0, -2);
	EXPECT_DOUBLE_EQ(r.summary().maxReach, 0.5);
	obs::RawlogReader::Sweep s;
	size_t sweeps = 0;
	while (r.next(s)) sweeps++;
	EXPECT_EQ(sweeps, 2u);
}
