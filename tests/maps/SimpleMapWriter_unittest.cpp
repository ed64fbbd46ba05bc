#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/maps/SimpleMapWriter.h>

#include <filesystem>

using namespace whiskermap;
namespace fs = std::filesystem;

namespace
{
std::vector<uint8_t> unzipped(const std::string& path)
{
	mrpt::io::CFileGZInputStream in(path);
	std::vector<uint8_t> out(1 << 20);
	out.resize(in.Read(out.data(), out.size()));
	return out;
}
}  // namespace

// Regression (issue 8): --simplemap kept every sweep in memory; the streamed file must be
// exactly what MRPT writes for the same entries.
TEST(SimpleMapWriter, StreamsTheBytesCSimpleMapWrites)
{
	const auto dir = fs::temp_directory_path();
	const auto ours = (dir / "whiskermap_stream.simplemap").string(), theirs = (dir / "whiskermap_mrpt.simplemap").string();
	mrpt::maps::CSimpleMap sm;
	maps::SimpleMapWriter w(ours, 3);
	for (int i = 0; i < 3; i++)
	{
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->odometry = mrpt::poses::CPose2D(i, -i, 0.1 * i);
		const mrpt::poses::CPose2D pose(0.5 * i, 2, 0.3);
		w.add(pose, odo);
		auto sf = mrpt::obs::CSensoryFrame::Create();
		sf->insert(odo);
		sm.insert(mrpt::poses::CPose3DPDFGaussian::Create(mrpt::poses::CPose3D(pose)), sf);
	}
	w.close();
	ASSERT_TRUE(sm.saveToFile(theirs));
	EXPECT_EQ(unzipped(ours), unzipped(theirs));
	mrpt::maps::CSimpleMap back;
	ASSERT_TRUE(back.loadFromFile(ours));
	EXPECT_EQ(back.size(), 3u);
	fs::remove(ours), fs::remove(theirs);
}

TEST(SimpleMapWriter, TheAnnouncedCountIsKept)
{
	const auto path = (fs::temp_directory_path() / "whiskermap_count.simplemap").string();
	maps::SimpleMapWriter w(path, 2);
	w.add({}, mrpt::obs::CObservationOdometry::Create());
	EXPECT_THROW(w.close(), core::Error);
	fs::remove(path);
}
