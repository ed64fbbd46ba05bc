#include "Fixtures.h"

#include <whiskermap/eval/Identifiability.h>
#include <whiskermap/world/RawlogWriter.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <map>
#include <set>

using namespace whiskermap;
using eval::Identifiability;

namespace
{
/** Table 0 near the middle (legs at x = 1.0, 2.0 and y = 1.2, 1.8), table 1 in a far corner,
 *  table 2 near the bottom right. */
world::World tinyWorld()
{
	world::World w;
	w.x_max = w.y_max = 4;
	w.tables = {test::table(1.5, 1.5, 0), test::table(3.3, 3.3, 90), test::table(3.3, 0.6, 0)};
	return w;
}

/** A sweep from the origin whose whiskers touched exactly these world points. */
obs::RawlogReader::Sweep touching(const std::vector<Eigen::Vector2d>& points, double sigmaR = 0)
{
	auto o = obs::CObservationWhiskerContacts::Create();
	o->noise.sigma_r = sigmaR;
	for (const auto& p : points)
	{
		obs::TWhisker w;
		w.length = 10;
		w.touched = true;
		w.angle = std::atan2(p.y(), p.x());
		w.r = p.norm();
		o->whiskers.push_back(w);
	}
	return {mrpt::poses::CPose2D(0, 0, 0), o};
}
}  // namespace

TEST(Identifiability, NeedsTwoDifferentLegs)
{
	const auto w = tinyWorld();
	// Two contacts on leg 0 (centre (2.0, 1.8)): still one leg.
	const auto oneLeg = touching({{2.025, 1.8}, {2.0, 1.825}});
	EXPECT_TRUE(Identifiability::of(w, {oneLeg, oneLeg}, 0.01).tables.empty());
	// Leg 0 and leg 2 (centre (1.0, 1.2)), in different sweeps.
	const auto id = Identifiability::of(w, {oneLeg, touching({{0.975, 1.2}})}, 0.01);
	EXPECT_EQ(id.tables, (std::vector<size_t>{0}));
	EXPECT_EQ(id.gate, 0.01);
}

TEST(Identifiability, GateDecidesWhatIsOnALeg)
{
	const auto w = tinyWorld();
	// 3 cm outside leg 1's face at x = 0.975, plus a contact on leg 0.
	const std::vector<obs::RawlogReader::Sweep> sweeps{touching({{0.945, 1.8}, {2.025, 1.8}})};
	EXPECT_EQ(Identifiability::of(w, sweeps, 0.04).tables.size(), 1u);
	EXPECT_TRUE(Identifiability::of(w, sweeps, 0.02).tables.empty());
}

TEST(Identifiability, DefaultGateAndRecall)
{
	EXPECT_NEAR(Identifiability::defaultGate({touching({}, 0.01), touching({}, 0.05)}), 0.16, 1e-12);
	EXPECT_NEAR(Identifiability::defaultGate({touching({})}), 0.01, 1e-12);
	Identifiability id;
	id.tables = {0, 2};
	eval::MapEvaluation e;
	e.truthMatch = {-1, 0, 1};
	EXPECT_EQ(id.recall(e), 0.5);
	e.truthMatch = {3, -1, -1};
	EXPECT_EQ(id.recall(e), 0.5);
	EXPECT_EQ(Identifiability{}.recall(e), 1.0);
}

class IdentifiabilityRawlog : public test::TempDirTest
{
};

TEST_F(IdentifiabilityRawlog, AgreesWithWhatTheSimulatorTouched)
{
	const auto w = tinyWorld();
	const auto robot = world::Robot::load(std::string(WHISKERMAP_SOURCE_DIR) + "/config/robots/scratchbot.ini");
	world::WhiskerSimulator sim(w, robot, {0.01, core::deg2rad(5), 0.05}, 2011);
	// Around table 0, facing it: table 0 is touched on all four legs, table 2 on one leg only,
	// table 1 (out of whisker reach) not at all.
	const std::vector<mrpt::poses::CPose2D> poses{
		{1.5, 0.7, M_PI_2}, {0.4, 1.5, 0}, {2.6, 1.5, M_PI}, {1.5, 2.3, -M_PI_2}};
	std::map<int, std::set<int>> legsTouched;  // by the simulator's own account
	world::RawlogWriter out(path("tiny.rawlog"), world::RawlogWriter::Format::Observations);
	std::vector<world::WhiskerSimulator::Truth> truth;
	for (size_t i = 0; i < poses.size(); i++)
	{
		ASSERT_TRUE(sim.poseIsFree(poses[i]));
		out.write(poses[i], *sim.sense(poses[i], mrpt::Clock::fromDouble(1e9 + i), &truth));
		for (const auto& t : truth)
			if (t.table >= 0) legsTouched[t.table].insert(t.leg);
	}
	out.close();

	std::vector<size_t> expected;
	for (const auto& [table, legs] : legsTouched)
		if (legs.size() >= 2) expected.push_back(size_t(table));
	// The scenario is what it should be.
	ASSERT_EQ(expected, (std::vector<size_t>{0}));
	ASSERT_EQ(legsTouched[2].size(), 1u);
	ASSERT_EQ(legsTouched.count(1), 0u);

	const auto sweeps = obs::RawlogReader::read(path("tiny.rawlog")).sweeps;
	ASSERT_EQ(sweeps.size(), poses.size());
	const double gate = Identifiability::defaultGate(sweeps);
	EXPECT_NEAR(gate, 0.04, 1e-12);
	EXPECT_EQ(Identifiability::of(w, sweeps, gate).tables, expected);
}
