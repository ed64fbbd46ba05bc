// whisker-export's and whisker-import's library path (ContactLogWriter -> ContactLogReader ->
// RawlogWriter) gives back the shipped datasets' sweeps: every field of every observation and
// every pose, bit for bit.
#include <gtest/gtest.h>
#include <whiskermap/obs/RawlogReader.h>
#include <whiskermap/world/ContactLogReader.h>
#include <whiskermap/world/ContactLogWriter.h>
#include <whiskermap/world/NoisePreset.h>
#include <whiskermap/world/RawlogWriter.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cstring>
#include <filesystem>

#include "../TempDirTest.h"

using namespace whiskermap;
namespace fs = std::filesystem;

namespace
{
const std::string SRC = WHISKERMAP_SOURCE_DIR;

/** Same bits: 0.0 and -0.0 differ, as they would in a rawlog. */
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSamePose(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b, size_t k)
{
	EXPECT_TRUE(same(a.x(), b.x()) && same(a.y(), b.y()) && same(a.phi(), b.phi()))
		<< "sweep " << k << ": " << a << " vs " << b;
}

void expectSameSweep(
	const obs::CObservationWhiskerContacts& a, const obs::CObservationWhiskerContacts& b, size_t k)
{
	EXPECT_EQ(a.timestamp, b.timestamp) << "sweep " << k;
	EXPECT_EQ(a.sensorLabel, b.sensorLabel) << "sweep " << k;
	for (int i = 0; i < 3; i++)
		EXPECT_TRUE(same(a.sensorPose.m_coords[i], b.sensorPose.m_coords[i]));
	for (int i = 0; i < 9; i++)
		EXPECT_TRUE(same(
			a.sensorPose.getRotationMatrix()(i / 3, i % 3),
			b.sensorPose.getRotationMatrix()(i / 3, i % 3)));
	EXPECT_TRUE(same(a.noise.sigma_r, b.noise.sigma_r));
	EXPECT_TRUE(same(a.noise.sigma_phi, b.noise.sigma_phi));
	EXPECT_TRUE(same(a.noise.sigma_tau, b.noise.sigma_tau));
	ASSERT_EQ(a.whiskers.size(), b.whiskers.size());
	for (size_t i = 0; i < a.whiskers.size(); i++)
	{
		const auto &u = a.whiskers[i], &v = b.whiskers[i];
		EXPECT_EQ(u.touched, v.touched) << "sweep " << k << " whisker " << i;
		const double fu[] = {u.mount_x, u.mount_y, u.sweep_start, u.sweep_end, u.length,
							 u.angle,	u.r,	   u.normal,	  u.texture};
		const double fv[] = {v.mount_x, v.mount_y, v.sweep_start, v.sweep_end, v.length,
							 v.angle,	v.r,	   v.normal,	  v.texture};
		for (size_t f = 0; f < 9; f++)
			EXPECT_TRUE(same(fu[f], fv[f])) << "sweep " << k << " whisker " << i << " field " << f
											<< ": " << fu[f] << " vs " << fv[f];
	}
}

class ContactLogRoundTrip : public test::TempDirTest
{
   protected:
	/** Exports `rawlog`, imports it back (robot scratchbot, `noise`) in layout `fmt`, and
	 *  returns the reimported rawlog as read; `direct` receives the reader's sweeps. */
	obs::RawlogReader::Contents roundTrip(
		const std::string& rawlog, const std::string& noise, world::RawlogWriter::Format fmt,
		std::vector<world::ContactLogReader::Sweep>& direct)
	{
		const auto csv = (dir / "log.csv").string(), back = (dir / "back.rawlog").string();
		world::ContactLogWriter w(csv, rawlog);
		obs::RawlogReader::forEach(
			rawlog, [&](const obs::RawlogReader::Sweep& s) { w.write(s.robotPose, *s.obs); });
		w.close();
		world::ContactLogReader r(
			csv, world::Robot::load(SRC + "/config/robots/scratchbot.ini"),
			world::NoisePreset::load(noise));
		world::RawlogWriter out(back, fmt, world::RawlogWriter::GroundTruth::None);
		for (world::ContactLogReader::Sweep s; r.next(s);)
		{
			out.write(s.odometry, *s.obs);
			direct.push_back(s);
		}
		out.close();
		return obs::RawlogReader::read(back);
	}
};
}  // namespace

TEST_F(ContactLogRoundTrip, ShippedDatasetsComeBackBitForBit)
{
	for (const std::string preset : {"noiseless", "default", "very-noisy"})
	{
		SCOPED_TRACE(preset);
		const auto original =
			obs::RawlogReader::read(SRC + "/datasets/paper_arena/" + preset + ".rawlog");
		std::vector<world::ContactLogReader::Sweep> direct;
		const auto back = roundTrip(
			SRC + "/datasets/paper_arena/" + preset + ".rawlog", preset,
			world::RawlogWriter::Format::Observations, direct);
		ASSERT_EQ(original.sweeps.size(), 400u);
		ASSERT_EQ(back.sweeps.size(), original.sweeps.size());
		ASSERT_EQ(direct.size(), original.sweeps.size());
		EXPECT_EQ(back.objects, original.objects);
		for (size_t k = 0; k < original.sweeps.size(); k++)
		{
			const auto& o = original.sweeps[k];
			expectSamePose(o.robotPose, direct[k].odometry, k);
			expectSameSweep(*o.obs, *direct[k].obs, k);
			expectSamePose(o.robotPose, back.sweeps[k].robotPose, k);
			expectSameSweep(*o.obs, *back.sweeps[k].obs, k);
		}
	}
}

TEST_F(ContactLogRoundTrip, ActionSensoryFrameLayoutKeepsSweepsExactlyAndPosesClosely)
{
	// The layout stores pose increments; the reader composes them. Importing recomputes the
	// increments from the composed poses, so the composed poses may move by rounding (on the
	// paper grid they do not); the sweeps are exact.
	const auto w = world::World::load(SRC + "/config/worlds/paper_arena.ini");
	world::WhiskerSimulator sim(
		w, world::Robot::load(SRC + "/config/robots/scratchbot.ini"),
		world::NoisePreset::load("default"), 11);
	const auto sf = (dir / "sf.rawlog").string();
	{
		world::RawlogWriter out(sf, world::RawlogWriter::Format::ActionSensoryFrame);
		double t = 1.3e9;
		for (const auto& p : world::Trajectory::paperGrid(w, 5, 5))
			if (sim.poseIsFree(p))
				out.write(p, *sim.sense(p, mrpt::Clock::fromDouble(t += 0.1234567)));
		out.close();
	}
	const auto original = obs::RawlogReader::read(sf);
	std::vector<world::ContactLogReader::Sweep> direct;
	const auto back =
		roundTrip(sf, "default", world::RawlogWriter::Format::ActionSensoryFrame, direct);
	EXPECT_TRUE(back.actionSensoryFrameFormat);
	ASSERT_GT(original.sweeps.size(), 50u);
	ASSERT_EQ(back.sweeps.size(), original.sweeps.size());
	for (size_t k = 0; k < original.sweeps.size(); k++)
	{
		expectSamePose(original.sweeps[k].robotPose, direct[k].odometry, k);
		expectSameSweep(*original.sweeps[k].obs, *back.sweeps[k].obs, k);
		EXPECT_LT((original.sweeps[k].robotPose - back.sweeps[k].robotPose).norm(), 1e-12);
	}
}
