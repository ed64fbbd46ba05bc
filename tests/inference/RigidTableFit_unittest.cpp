// inference::fitRigidTable: the reported pose of a lasting table (doc/map-plugin.md). Hand-made
// states: a known table whose legs stand loose around its corners (as eq. 6 lets them) and
// whose own pose is off; the rigid fit to the legs' contacts finds the true pose, from
// explicit contacts and from folded evidence alike, and weighs each contact by its shaft.
#include <gtest/gtest.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/RigidPoseSpread.h>
#include <whiskermap/inference/RigidTableFit.h>
#include <whiskermap/model/LegEvidence.h>

#include <cmath>
#include <random>
#include <vector>

#include "SyntheticTable.h"

using namespace whiskermap;

namespace
{
const model::Table TRUTH{1.0, 2.0, 0.3, 0.05, 0.7};

/** Two faces on each of corners 0, 1, 2; every shaft at 60 degrees to its contact's normal. */
std::vector<obs::Shapelet> contacts(const model::ModelParams& p)
{
	auto s = test::touchTable(
		TRUTH, p, {{0, 0, 0.01}, {0, 1, -0.01}, {0, 0, -0.012}, {1, 1, 0.01}, {1, 2, -0.01}, {1, 2, 0.015},
				   {2, 2, 0.01}, {2, 3, -0.01}, {2, 3, 0.012}});
	for (auto& c : s)
	{
		const double a = c.normal + M_PI + M_PI / 3;  // pointing into the leg, 60 degrees off its normal
		c.shaft_x = std::cos(a), c.shaft_y = std::sin(a);
	}
	return s;
}

/** A state holding one table at a pose off the truth, legs 4 mm off their corners (explicit
 *  contacts, or folded into the legs' evidence when `fold`). */
model::LastingState state(const model::ModelParams& p, const std::vector<obs::Shapelet>& s, bool fold)
{
	model::Table off = TRUTH;
	off.x += 0.004, off.y -= 0.003, off.theta += 0.01;
	std::vector<model::Leg> legs(3);
	std::vector<model::LegEvidence> evidence(3);
	for (int k = 0; k < 3; k++)
	{
		auto& l = legs[static_cast<size_t>(k)];
		model::tableCorner(TRUTH, k, p, l.x, l.y);
		l.x += 0.004 * (k - 1), l.y += 0.004 * (k % 2);
		l.theta = TRUTH.theta + 0.02;
		l.wx = l.wy = p.leg_width;
		l.texture = TRUTH.texture;
		l.parent = 0;
	}
	std::vector<model::LastingState::Contact> kept;
	for (size_t i = 0; i < s.size(); i++)
	{
		const size_t leg = i / 3;
		if (fold)
			evidence[leg].add(s[i], legs[leg], p);
		else
			kept.push_back({s[i], static_cast<model::Id>(leg), i});
	}
	model::LastingState st(p);
	st.restore({off}, {1.0}, {}, legs, evidence, kept, s.size(), p);
	return st;
}

double distance(const model::Table& a, const model::Table& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

TEST(RigidTableFit, FindsTheTruePoseFromExplicitContacts)
{
	model::ModelParams p;
	p.shaft_noise = true;
	const auto st = state(p, contacts(p), false);
	ASSERT_GT(distance(st.table(0), TRUTH), 0.004);
	const model::Table fit = inference::fitRigidTable(st, 0, p);
	// Not exactly the truth: eq. 7's 1-D normaliser under shaft noise depends on the faces'
	// yaw, so the likelihood's maximum is 0.2 mrad from the noiseless truth (0.05 mm here).
	EXPECT_LT(distance(fit, TRUTH), 1e-4);
	EXPECT_NEAR(fit.theta, TRUTH.theta, 3e-4);
	EXPECT_EQ(fit.texture, st.table(0).texture);
}

TEST(RigidTableFit, FindsTheTruePoseFromFoldedEvidence)
{
	const model::ModelParams p;
	const auto st = state(p, contacts(p), true);
	ASSERT_TRUE(st.contactsOf(0).empty());
	const model::Table fit = inference::fitRigidTable(st, 0, p);
	EXPECT_LT(distance(fit, TRUTH), 2e-5);
	EXPECT_NEAR(fit.theta, TRUTH.theta, 1e-4);
}

// Readings that err along their shafts (1 cm, shafts 10-85 degrees off the faces' normals):
// the fit under shaft noise is the better estimator, over 40 draws (fixed seed), than the
// same fit with the paper's isotropic eq. 7 (measured: 4.0 mm against 4.9 mm RMS).
TEST(RigidTableFit, ShaftNoiseFitsReadingsThatErrAlongTheirShafts)
{
	model::ModelParams shaft, isotropic;
	shaft.shaft_noise = true;
	std::mt19937 rng(7);
	std::normal_distribution<double> err(0, 0.01);
	double sum2[2] = {0, 0};
	for (int draw = 0; draw < 40; draw++)
	{
		auto s = contacts(shaft);
		for (size_t i = 0; i < s.size(); i++)
		{
			const double off = core::deg2rad(10 + 75.0 * static_cast<double>(i) / static_cast<double>(s.size() - 1));
			const double a = s[i].normal + M_PI + (i % 2 ? off : -off);
			s[i].shaft_x = std::cos(a), s[i].shaft_y = std::sin(a);
			const double e = err(rng);
			s[i].x += e * s[i].shaft_x, s[i].y += e * s[i].shaft_y;
		}
		for (const bool on : {false, true})
		{
			const auto& p = on ? shaft : isotropic;
			sum2[on] += std::pow(distance(inference::fitRigidTable(state(p, s, false), 0, p), TRUTH), 2);
		}
	}
	const double rmsShaft = std::sqrt(sum2[1] / 40), rmsIsotropic = std::sqrt(sum2[0] / 40);
	EXPECT_LT(rmsShaft, 0.9 * rmsIsotropic) << rmsShaft << " m against " << rmsIsotropic << " m";
}

TEST(RigidTableFit, TableWithoutLegsKeepsItsPose)
{
	const model::ModelParams p;
	model::LastingState st(p);
	st.restore({TRUTH}, {1.0}, {}, {}, {}, {}, 0, p);
	const model::Table fit = inference::fitRigidTable(st, 0, p);
	EXPECT_EQ(fit.x, TRUTH.x);
	EXPECT_EQ(fit.y, TRUTH.y);
	EXPECT_EQ(fit.theta, TRUTH.theta);
}

namespace
{
/** What the fit maximises, written out again: eq. 7 summed over each leg's contacts with
 *  the leg rigid at its corner of `table` (eq. 6 without slack). */
double rigidScore(const model::LastingState& st, const model::Table& table, const model::ModelParams& p)
{
	double v = 0;
	for (const model::Id l : st.legsOf(0))
	{
		model::Leg leg = st.leg(l);
		model::tableCorner(table, leg.corner, p, leg.x, leg.y);
		leg.theta = table.theta;
		v += st.evidence(l).logLikelihood(leg, p);
		for (const model::Id c : st.contactsOf(l)) v += model::logShapeletGivenLeg(st.contact(c).shapelet, leg, p);
	}
	return v;
}
}  // namespace

// The fit is a maximum at the search's resolution: no step of 0.02 mm or 0.02 mrad in any
// direction scores higher, on noisy readings (where the optimum is not the truth) under both
// noise models, from explicit contacts and from folded evidence.
TEST(RigidTableFit, NoSmallStepImprovesTheFit)
{
	std::mt19937 rng(11);
	std::normal_distribution<double> err(0, 0.003);
	for (const bool shaftNoise : {false, true})
		for (const bool fold : {false, true})
		{
			model::ModelParams p;
			p.shaft_noise = shaftNoise;
			auto s = contacts(p);
			for (auto& c : s) c.x += err(rng), c.y += err(rng);
			const auto st = state(p, s, fold);
			const model::Table fit = inference::fitRigidTable(st, 0, p);
			const double best = rigidScore(st, fit, p);
			for (int k = 0; k < 6; k++)
			{
				model::Table c = fit;
				const double d = k % 2 ? -2e-5 : 2e-5;
				(k < 2 ? c.x : k < 4 ? c.y : c.theta) += d;
				EXPECT_LE(rigidScore(st, c, p), best + 1e-9) << "shaft " << shaftNoise << " fold " << fold << " step " << k;
			}
		}
}

// The pose spread (inference::rigidPoseSpread) is calibrated: over 200 sets of readings drawn
// with the model's own noise (eq. 7 is exp(-(d / sigma_r)^2 - (a / sigma_theta)^2): standard
// deviations sigma_r / sqrt 2 on the distance, sigma_theta / sqrt 2 on the normal), the truth
// lies within two reported standard deviations of the fit about 95% of the time, on each
// axis. A spread half or twice as wide would cover about 68% or 99.99%; drawn with sigma_r
// and sigma_theta themselves (twice the variance), 85-87%.
TEST(RigidPoseSpread, TwoStandardDeviationsCoverTheTruthAboutNinetyFivePercentOfTheTime)
{
	const model::ModelParams p;
	std::mt19937 rng(5);
	std::normal_distribution<double> position(0, p.sigma_r / std::sqrt(2.0)), normal(0, p.sigma_theta / std::sqrt(2.0));
	constexpr int TRIALS = 200;
	int covered[3] = {0, 0, 0};
	double acceptance = 0;
	for (int k = 0; k < TRIALS; k++)
	{
		auto s = contacts(p);
		for (auto& c : s) c.x += position(rng), c.y += position(rng), c.normal += normal(rng);
		const auto st = state(p, s, false);
		const model::Table fit = inference::fitRigidTable(st, 0, p);
		const inference::PoseSpread spread = inference::rigidPoseSpread(st, 0, fit, p, k);
		covered[0] += std::abs(fit.x - TRUTH.x) <= 2 * spread.sd_x;
		covered[1] += std::abs(fit.y - TRUTH.y) <= 2 * spread.sd_y;
		covered[2] += std::abs(core::angleDiff(fit.theta, TRUTH.theta, M_PI)) <= 2 * spread.sd_yaw;
		acceptance += spread.acceptance / TRIALS;
	}
	std::printf("within 2 sd: x %d, y %d, yaw %d of %d; acceptance %.2f\n", covered[0], covered[1], covered[2], TRIALS, acceptance);
	for (const int c : covered)
	{
		EXPECT_GE(c, 0.88 * TRIALS);
		EXPECT_LE(c, 0.99 * TRIALS);
	}
	EXPECT_GT(acceptance, 0.15);  // the Laplace-scaled proposal mixes (about 0.3 expected in 3-D)
	EXPECT_LT(acceptance, 0.6);
}

// More contacts, narrower spread: each contact read four times halves the standard
// deviations (the score's curvature grows fourfold). Same seed, same answer.
TEST(RigidPoseSpread, ShrinksWithTheContactsAndIsReproducible)
{
	const model::ModelParams p;
	auto once = contacts(p);
	auto four = std::vector<obs::Shapelet>();
	for (const auto& c : once)
		for (int r = 0; r < 4; r++) four.push_back(c);
	const auto a = state(p, once, false);
	// state() puts contact i on leg i / 3: four copies of 9 contacts need legs of 12.
	std::vector<obs::Shapelet> regrouped;
	for (int leg = 0; leg < 3; leg++)
		for (int r = 0; r < 4; r++)
			for (int i = 0; i < 3; i++) regrouped.push_back(once[static_cast<size_t>(3 * leg + i)]);
	model::LastingState b(p);
	{
		std::vector<model::Leg> legs;
		std::vector<model::LegEvidence> evidence(3);
		std::vector<model::LastingState::Contact> kept;
		for (model::Id l = 0; l < 3; l++) legs.push_back(a.leg(l));
		for (size_t i = 0; i < regrouped.size(); i++) kept.push_back({regrouped[i], static_cast<model::Id>(i / 12), i});
		b.restore({a.table(0)}, {1.0}, {}, legs, evidence, kept, regrouped.size(), p);
	}
	const model::Table fa = inference::fitRigidTable(a, 0, p), fb = inference::fitRigidTable(b, 0, p);
	const inference::PoseSpread sa = inference::rigidPoseSpread(a, 0, fa, p, 3);
	const inference::PoseSpread sb = inference::rigidPoseSpread(b, 0, fb, p, 3);
	EXPECT_NEAR(sb.sd_x / sa.sd_x, 0.5, 0.1);
	EXPECT_NEAR(sb.sd_y / sa.sd_y, 0.5, 0.1);
	EXPECT_NEAR(sb.sd_yaw / sa.sd_yaw, 0.5, 0.1);
	const inference::PoseSpread again = inference::rigidPoseSpread(a, 0, fa, p, 3);
	EXPECT_EQ(again.sd_x, sa.sd_x);
	EXPECT_EQ(again.sd_yaw, sa.sd_yaw);
	EXPECT_NE(inference::rigidPoseSpread(a, 0, fa, p, 4).sd_x, sa.sd_x);
}
