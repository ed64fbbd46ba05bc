#pragma once
#include <gtest/gtest.h>
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/moves/MoveContext.h>
#include <whiskermap/model/Posterior.h>

#include "SyntheticTable.h"

#include <cmath>
#include <random>

namespace whiskermap::test
{
/** A blackboard and a MoveContext on it (default sampler parameters), for the move tests. */
struct ContextOnBoard
{
	explicit ContextOnBoard(const model::ModelParams& params = {}) : P(params), bb(P), ctx(bb, P, S, rng, acceptance)
	{
		ctx.result = &result;
	}

	const model::ModelParams P;
	const inference::SamplerParams S;
	model::Blackboard bb;
	inference::SamplerRandom rng;
	inference::Acceptance acceptance;
	inference::StepResult result;
	inference::moves::MoveContext ctx;
};

/** A small random blackboard for the move tests: the contacts of 2-4 touches on a random table
 *  (1 mm position noise), one leg per touched corner explaining them, under the table or free
 *  (`withTable`), each leg refitted to its contacts; and a MoveContext on it. */
class MoveBoard : public ContextOnBoard
{
   public:
	MoveBoard(uint64_t seed, bool withTable, const model::ModelParams& params = {})
		: ContextOnBoard(params), m_random(seed)
	{
		rng.seed(seed);
		std::uniform_real_distribution<double> u(0, 1);
		const model::Table t{u(m_random) * 4 - 2, u(m_random) * 4 - 2, u(m_random) * M_PI, P.leg_width, P.texture};
		std::vector<Touch> touches;
		const int n = 2 + static_cast<int>(u(m_random) * 3);
		for (int i = 0; i < n; i++)
			touches.push_back({static_cast<int>(u(m_random) * 4), static_cast<int>(u(m_random) * 4),
							   (u(m_random) - 0.5) * P.leg_width * 0.6});
		std::vector<obs::Shapelet> shapelets = touchTable(t, P, touches);
		for (obs::Shapelet& s : shapelets) s.x += (u(m_random) - 0.5) * 2e-3, s.y += (u(m_random) - 0.5) * 2e-3;
		bb.reset(shapelets);
		table = withTable ? bb.addTable(t) : model::NONE;
		model::Id legAt[4] = {model::NONE, model::NONE, model::NONE, model::NONE};
		for (size_t i = 0; i < touches.size(); i++)
		{
			model::Id& l = legAt[touches[i].corner];
			if (l == model::NONE)
			{
				model::Leg leg;
				model::tableCorner(t, touches[i].corner, P, leg.x, leg.y);
				leg.theta = t.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture, leg.parent = table;
				l = bb.addLeg(leg);
			}
			bb.setShapeletParent(i, l);
		}
		for (int round = 0; round < 2; round++)
			for (const model::Id l : legAt)
				if (l != model::NONE)
				{
					double ignored = 0;
					ctx.refitInPlace(l, ignored);
				}
	}

	/** A uniform index below n from the test's own generator. */
	size_t pick(size_t n) { return static_cast<size_t>(std::uniform_real_distribution<double>(0, 1)(m_random) * static_cast<double>(n)); }
	/** The live legs. */
	std::vector<model::Id> legs() const
	{
		std::vector<model::Id> out;
		for (model::Id l = 0; l < bb.legIdBound(); l++)
			if (bb.hasLeg(l)) out.push_back(l);
		return out;
	}

	model::Id table = model::NONE;

   private:
	std::mt19937_64 m_random;
};

/** Same live hypotheses, links and poses (to 1e-9). */
inline void expectSameBoard(const model::Blackboard& a, const model::Blackboard& b, const char* what)
{
	const model::HypothesisSet x = a.compact(), y = b.compact();
	ASSERT_EQ(x.tables.size(), y.tables.size()) << what;
	ASSERT_EQ(x.legs.size(), y.legs.size()) << what;
	EXPECT_EQ(x.shapeletParent, y.shapeletParent) << what;
	constexpr double EPS = 1e-9;
	for (size_t i = 0; i < x.tables.size(); i++)
	{
		EXPECT_NEAR(x.tables[i].x, y.tables[i].x, EPS) << what;
		EXPECT_NEAR(x.tables[i].y, y.tables[i].y, EPS) << what;
		EXPECT_NEAR(x.tables[i].theta, y.tables[i].theta, EPS) << what;
	}
	for (size_t i = 0; i < x.legs.size(); i++)
	{
		EXPECT_NEAR(x.legs[i].x, y.legs[i].x, EPS) << what;
		EXPECT_NEAR(x.legs[i].y, y.legs[i].y, EPS) << what;
		EXPECT_NEAR(x.legs[i].theta, y.legs[i].theta, EPS) << what;
		EXPECT_NEAR(x.legs[i].texture, y.legs[i].texture, EPS) << what;
		EXPECT_EQ(x.legs[i].parent, y.legs[i].parent) << what;
	}
}

/** A move and then its reverse: the changes of logJoint and the log proposal ratios
 *  log q(fwd)/q(rev) of the two are negatives of each other (to 1e-9). */
inline void expectReverses(const inference::moves::Proposal& f, const inference::moves::Proposal& r, const char* what)
{
	EXPECT_NEAR(f.logTarget + r.logTarget, 0, 1e-9) << what;
	EXPECT_NEAR((f.logForward - f.logReverse) + (r.logForward - r.logReverse), 0, 1e-9) << what;
	EXPECT_EQ(f.logJacobian + r.logJacobian, 0) << what;
}
}  // namespace whiskermap::test
