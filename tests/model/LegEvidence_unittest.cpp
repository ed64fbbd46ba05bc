#include <gtest/gtest.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/LegEvidence.h>

#include <cmath>
#include <random>
#include <vector>

using namespace whiskermap::model;
using whiskermap::obs::Shapelet;

namespace
{
std::mt19937_64 rng(7);
double u(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

/** Contacts on the middle half of random faces of leg l, with noisy normals and textures. */
std::vector<Shapelet> contactsOn(const Leg& l, int n)
{
	std::vector<Shapelet> out;
	for (int i = 0; i < n; i++)
	{
		const int face = static_cast<int>(rng() % 4);
		const double a = l.theta + face * M_PI_2, h = (face % 2 ? l.wy : l.wx) / 2, along = u(-0.2, 0.2) * l.wx;
		Shapelet s;
		const double depth = h + u(-0.001, 0.004);
		s.x = l.x + depth * std::cos(a) - along * std::sin(a);
		s.y = l.y + depth * std::sin(a) + along * std::cos(a);
		s.normal = a + u(-0.2, 0.2);
		s.texture = u(0.4, 0.9);
		const double shaft = u(-M_PI, M_PI);  // used by shaft noise only
		s.shaft_x = std::cos(shaft), s.shaft_y = std::sin(shaft);
		out.push_back(s);
	}
	return out;
}
}  // namespace

// Folded contacts score exactly as eq. 7 scores them one by one, at the leg they were folded
// with and at nearby poses that keep every contact on its face (turns of up to 6 degrees,
// shifts of up to 3 mm, other textures): the sufficient statistics lose nothing there.
TEST(LegEvidence, EqualsEq7SummedOverItsContacts)
{
	ModelParams p;
	for (int trial = 0; trial < 200; trial++)
	{
		const Leg l{u(-50, 50), u(-50, 50), u(-M_PI, M_PI), p.leg_width, p.leg_width, 0.7, NONE, -1};
		const auto contacts = contactsOn(l, 1 + static_cast<int>(rng() % 12));
		LegEvidence e;
		for (const auto& s : contacts) e.add(s, l, p);
		ASSERT_EQ(e.count(), contacts.size());
		for (int k = 0; k < 5; k++)
		{
			Leg m = l;
			if (k > 0)
			{
				m.x += u(-0.003, 0.003), m.y += u(-0.003, 0.003), m.texture = u(0, 1);
				m.theta += u(-0.1, 0.1) + static_cast<int>(rng() % 4) * M_PI_2;  // a square: same leg
			}
			double sum = 0;
			for (const auto& s : contacts) sum += logShapeletGivenLeg(s, m, p);
			EXPECT_NEAR(e.logLikelihood(m, p), sum, 1e-7 * std::abs(sum)) << "trial " << trial << " pose " << k;
		}
	}
}

// With shaft noise each contact weighs by its own variance across its face: still exact at
// poses that keep every contact on its face and the faces' directions (shifts, quarter turns).
TEST(LegEvidence, EqualsEq7WithShaftNoise)
{
	ModelParams p;
	p.shaft_noise = true;
	for (int trial = 0; trial < 200; trial++)
	{
		const Leg l{u(-50, 50), u(-50, 50), u(-M_PI, M_PI), p.leg_width, p.leg_width, 0.7, NONE, -1};
		const auto contacts = contactsOn(l, 1 + static_cast<int>(rng() % 12));
		LegEvidence e;
		for (const auto& s : contacts) e.add(s, l, p);
		for (int k = 0; k < 5; k++)
		{
			Leg m = l;
			m.x += u(-0.001, 0.001), m.y += u(-0.001, 0.001), m.texture = u(0, 1);
			m.theta += static_cast<int>(rng() % 4) * M_PI_2;
			double sum = 0;
			for (const auto& s : contacts) sum += logShapeletGivenLeg(s, m, p);
			EXPECT_NEAR(e.logLikelihood(m, p), sum, 1e-7 * std::abs(sum)) << "trial " << trial << " pose " << k;
		}
	}
}

// Both kinds of face moments are kept whichever model folds: evidence folded with the paper's
// eq. 7 scores as eq. 7 under shaft noise (what the reported pose fits), and the reverse.
TEST(LegEvidence, ScoresUnderTheOtherNoiseModelToo)
{
	ModelParams paper, shaft;
	shaft.shaft_noise = true;
	for (int trial = 0; trial < 100; trial++)
	{
		const Leg l{u(-5, 5), u(-5, 5), u(-M_PI, M_PI), paper.leg_width, paper.leg_width, 0.7, NONE, -1};
		const auto contacts = contactsOn(l, 1 + static_cast<int>(rng() % 12));
		for (const bool foldWithShaft : {false, true})
		{
			const ModelParams &fold = foldWithShaft ? shaft : paper, &score = foldWithShaft ? paper : shaft;
			LegEvidence e;
			for (const auto& s : contacts) e.add(s, l, fold);
			Leg m = l;
			m.x += u(-0.001, 0.001), m.y += u(-0.001, 0.001);
			double sum = 0;
			for (const auto& s : contacts) sum += logShapeletGivenLeg(s, m, score);
			EXPECT_NEAR(e.logLikelihood(m, score), sum, 1e-7 * std::abs(sum)) << "trial " << trial;
		}
	}
}

// A version-2 stream held one set of face moments (34 numbers): both kinds read it.
TEST(LegEvidence, OlderStatsServeBothKinds)
{
	ModelParams paper, shaft;
	shaft.shaft_noise = true;
	const Leg l{1, 2, 0.3, paper.leg_width, paper.leg_width, 0.7, NONE, -1};
	LegEvidence e;
	for (const auto& s : contactsOn(l, 6)) e.add(s, l, paper);
	auto v = e.stats();
	for (size_t k = 34; k < v.size(); k++) v[k] = 0;  // what a version-2 reader leaves
	const LegEvidence old = LegEvidence::fromStats(v, e.count(), 34);
	Leg m = l;
	m.x += 0.002;
	EXPECT_DOUBLE_EQ(old.logLikelihood(m, paper), e.logLikelihood(m, paper));
	EXPECT_DOUBLE_EQ(old.logLikelihood(m, shaft) - old.logLikelihood(l, shaft), e.logLikelihood(m, paper) - e.logLikelihood(l, paper));
}

// Merging the evidence of two legs (folded at different poses, yaws a quarter turn apart, as
// when two legs are merged) scores as the two did apart, at any pose.
TEST(LegEvidence, MergeAddsTheTwoScores)
{
	ModelParams p;
	for (int trial = 0; trial < 100; trial++)
	{
		const Leg a{u(-5, 5), u(-5, 5), u(-M_PI, M_PI), p.leg_width, p.leg_width, 0.7, NONE, -1};
		Leg b = a;
		b.x += u(-0.003, 0.003), b.theta += M_PI_2 + u(-0.05, 0.05);
		LegEvidence ea, eb;
		for (const auto& s : contactsOn(a, 5)) ea.add(s, a, p);
		for (const auto& s : contactsOn(b, 4)) eb.add(s, b, p);
		LegEvidence merged = ea;
		merged.merge(eb);
		EXPECT_EQ(merged.count(), 9u);
		Leg m = a;
		m.x += u(-0.002, 0.002), m.theta += u(-0.1, 0.1);
		const double expected = ea.logLikelihood(m, p) + eb.logLikelihood(m, p);
		EXPECT_NEAR(merged.logLikelihood(m, p), expected, 1e-7 * std::abs(expected)) << trial;
	}
}

// The statistics survive a round trip through their serialized form; empty evidence scores 0.
TEST(LegEvidence, StatsRoundTripAndEmpty)
{
	ModelParams p;
	const Leg l{1, 2, 0.3, p.leg_width, p.leg_width, 0.7, NONE, -1};
	LegEvidence e;
	EXPECT_TRUE(e.empty());
	EXPECT_EQ(e.logLikelihood(l, p), 0);
	for (const auto& s : contactsOn(l, 6)) e.add(s, l, p);
	EXPECT_EQ(LegEvidence::fromStats(e.stats(), e.count()), e);
	EXPECT_FALSE(LegEvidence::fromStats(e.stats(), e.count() + 1) == e);
}

// Contacts folded with a noisier model weigh less: the same misfit costs less.
TEST(LegEvidence, WeightsFollowTheNoiseOfTheModel)
{
	ModelParams tight, loose;
	loose.sigma_r *= 5, loose.sigma_theta *= 3, loose.sigma_tau *= 2;
	const Leg l{0, 0, 0, tight.leg_width, tight.leg_width, 0.7, NONE, -1};
	const auto contacts = contactsOn(l, 8);
	LegEvidence a, b;
	for (const auto& s : contacts) a.add(s, l, tight), b.add(s, l, loose);
	Leg off = l;
	off.x += 0.01;
	const double base = 8 * std::log(tight.alpha_S);
	EXPECT_LT(a.logLikelihood(off, tight) - base, b.logLikelihood(off, tight) - base);
}
