#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/obs/CObservationWhiskerContacts.h>

#include <cmath>

#include "SampleSweep.h"
#include <cstdlib>
#include <cstring>

using whiskermap::obs::CObservationWhiskerContacts;
using whiskermap::obs::TWhisker;

namespace
{
const std::string FIXTURE = std::string(WHISKERMAP_SOURCE_DIR) + "/tests/data/whisker_contacts_v0.bin";

CObservationWhiskerContacts sample() { return whiskermap::test::sampleSweep(0, 0.03); }

void expectSame(const CObservationWhiskerContacts& x, const CObservationWhiskerContacts& y)
{
	EXPECT_EQ(x.timestamp, y.timestamp);
	EXPECT_EQ(x.sensorLabel, y.sensorLabel);
	EXPECT_EQ(x.sensorPose, y.sensorPose);
	EXPECT_EQ(x.noise.sigma_r, y.noise.sigma_r);
	EXPECT_EQ(x.noise.sigma_phi, y.noise.sigma_phi);
	EXPECT_EQ(x.noise.sigma_tau, y.noise.sigma_tau);
	ASSERT_EQ(x.whiskers.size(), y.whiskers.size());
	for (size_t i = 0; i < x.whiskers.size(); i++)
	{
		const auto &a = x.whiskers[i], &b = y.whiskers[i];
		EXPECT_EQ(a.touched, b.touched);
		for (auto [u, v] : {std::pair{a.mount_x, b.mount_x}, {a.mount_y, b.mount_y},
							{a.sweep_start, b.sweep_start}, {a.sweep_end, b.sweep_end},
							{a.length, b.length}, {a.angle, b.angle}, {a.r, b.r},
							{a.normal, b.normal}, {a.texture, b.texture}})
			EXPECT_EQ(u, v) << "whisker " << i;
	}
}

std::string validationError(const CObservationWhiskerContacts& o)
{
	try
	{
		o.validate();
	}
	catch (const whiskermap::core::Error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(CObservationWhiskerContacts, IsRegisteredWithMrpt)
{
	const auto* cls = mrpt::rtti::findRegisteredClass("whiskermap::obs::CObservationWhiskerContacts");
	ASSERT_NE(cls, nullptr);
	EXPECT_NE(std::dynamic_pointer_cast<CObservationWhiskerContacts>(cls->createObject()), nullptr);
}

TEST(CObservationWhiskerContacts, SerializationRoundTrip)
{
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	const auto original = sample();
	arch << original;
	buf.Seek(0);
	auto back = std::dynamic_pointer_cast<CObservationWhiskerContacts>(arch.ReadObject());
	ASSERT_TRUE(back);
	expectSame(original, *back);
}

TEST(CObservationWhiskerContacts, FileWrittenByVersion0StillLoads)
{
	if (std::getenv("WHISKERMAP_WRITE_FIXTURES"))
	{
		mrpt::io::CFileGZOutputStream f(FIXTURE);
		mrpt::serialization::archiveFrom(f) << sample();
	}
	mrpt::io::CFileGZInputStream f(FIXTURE);
	ASSERT_TRUE(f.fileOpenCorrectly()) << FIXTURE;
	auto obj = mrpt::serialization::archiveFrom(f).ReadObject();
	auto back = std::dynamic_pointer_cast<CObservationWhiskerContacts>(obj);
	ASSERT_TRUE(back);
	expectSame(sample(), *back);
}

TEST(CObservationWhiskerContacts, LoadRejectsInvalidValues)
{
	auto bad = sample();
	bad.whiskers[0].r = std::nan("");
	// Serialize without validation (serializeTo does not validate), then load: must throw.
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << bad;
	buf.Seek(0);
	try
	{
		arch.ReadObject();
		ADD_FAILURE() << "NaN reading loaded";
	}
	catch (const std::exception& e)
	{
		EXPECT_NE(std::string(e.what()).find("whisker 0: non-finite"), std::string::npos);
	}
}

TEST(CObservationWhiskerContacts, ValidateNamesWhiskerAndProblem)
{
	EXPECT_EQ(validationError(sample()), "");
	auto o = sample();
	o.whiskers[0].r = -0.01;
	EXPECT_NE(validationError(o).find("whisker 0: negative range"), std::string::npos);
	o = sample();
	o.whiskers[0].r = 0.61;
	EXPECT_NE(validationError(o).find("past the whisker length"), std::string::npos);
	o = sample();
	o.whiskers[1].normal = INFINITY;
	EXPECT_NE(validationError(o).find("whisker 1: non-finite"), std::string::npos);
	o = sample();
	o.whiskers[0].angle = 3.0;  // outside its sweep [0.2, 2.9]
	EXPECT_NE(validationError(o).find("outside its sweep"), std::string::npos);
	o = sample();
	o.whiskers.clear();
	EXPECT_NE(validationError(o).find("whisker count 0"), std::string::npos);
	o = sample();
	o.whiskers.resize(CObservationWhiskerContacts::MAX_WHISKERS + 1, o.whiskers[0]);
	EXPECT_NE(validationError(o).find("whisker count"), std::string::npos);
	o = sample();
	o.noise.sigma_r = -1;
	EXPECT_NE(validationError(o).find("noise std-dev"), std::string::npos);
}

TEST(CObservationWhiskerContacts, ShapeletsInWorldFrame)
{
	const auto o = sample();
	// Robot at (1, 2) facing +y. Sensor 0.08 ahead -> (1, 2.08). Whisker 0 pivots at
	// (0, 0.03) in the sensor frame -> world (0.97, 2.08); it points along the sensor's +y
	// (angle pi/2), i.e. world -x, and touched at r = 0.25 -> (0.72, 2.08). Normal -pi/2 in
	// the sensor frame is world 0 (+x), facing back at the robot.
	const auto s = o.toShapelets(mrpt::poses::CPose2D(1, 2, M_PI / 2));
	ASSERT_EQ(s.size(), 1u);  // the untouched whisker gives no shapelet
	EXPECT_NEAR(s[0].x, 0.72, 1e-12);
	EXPECT_NEAR(s[0].y, 2.08, 1e-12);
	EXPECT_NEAR(s[0].normal, 0, 1e-12);
	EXPECT_DOUBLE_EQ(s[0].texture, 0.7);
	EXPECT_EQ(s[0].whisker, 0);
	EXPECT_NEAR(s[0].shaft_x, -1, 1e-12);  // the shaft points along world -x
	EXPECT_NEAR(s[0].shaft_y, 0, 1e-12);
	EXPECT_EQ(o.contactCount(), 1u);
}

TEST(CObservationWhiskerContacts, ExportTxtHasOneColumnPerHeaderName)
{
	const auto o = sample();
	std::istringstream h(o.exportTxtHeader()), r(o.exportTxtDataRow());
	std::string w;
	size_t nh = 0, nr = 0;
	while (h >> w) nh++;
	while (r >> w) nr++;
	EXPECT_EQ(nh, 10u);
	EXPECT_EQ(nr, nh);
}

// Regression (issue 8): the stored label's length was trusted (a 4 KB file took 4 GB) and a
// bool byte other than 0/1 loaded as an invalid bool. Read by MRPT's own ReadObject, as
// stock tools given our plugin do.
TEST(CObservationWhiskerContacts, StoredLengthsAndBoolsAreCheckedBeforeUse)
{
	mrpt::io::CMemoryStream m;
	mrpt::serialization::archiveFrom(m) << sample();
	std::vector<uint8_t> good(static_cast<const uint8_t*>(m.getRawBufferData()),
							  static_cast<const uint8_t*>(m.getRawBufferData()) + m.getTotalBytesCount());
	const size_t header = 2 + std::strlen("whiskermap::obs::CObservationWhiskerContacts");
	auto load = [](const std::vector<uint8_t>& bytes) -> std::string {
		mrpt::io::CMemoryStream in;
		in.assignMemoryNotOwn(bytes.data(), bytes.size());
		try
		{
			CObservationWhiskerContacts o;
			mrpt::serialization::archiveFrom(in).ReadObject(&o);
		}
		catch (const std::exception& e)
		{
			return e.what();
		}
		return "";
	};
	EXPECT_EQ(load(good), "");
	auto label = good;
	const uint32_t huge = 0xfffffff0u;
	std::memcpy(&label[header + 8], &huge, 4);
	EXPECT_NE(load(label).find("stored sensor label length 4294967280"), std::string::npos) << load(label);
	auto touched = good;
	const size_t whisker0 = header + 8 + 4 + 8 + 2 + std::strlen("mrpt::poses::CPose3D") + 96 + 1 + 24 + 4;
	touched[whisker0 + 40] = 2;
	EXPECT_NE(load(touched).find("bool byte 2 is not 0 or 1"), std::string::npos) << load(touched);
}
