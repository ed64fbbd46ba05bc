#pragma once
// Small problems on continuous poses whose posterior is known by quadrature, for the tests of
// the reversible-jump chains (ReversibleJumpCells_unittest, LibraryScan_unittest).
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/model/Densities.h>

#include "MoveBoards.h"
#include "PoseQuadrature.h"

#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace whiskermap::test
{
/** One contact on a leg's face, under a model in which its leg is about as probable as none
 *  (alpha_S = 300; the defaults give 1 - 1e-4), with broad proposals judged by the
 *  reversible-jump rule. */
struct OneContact
{
	OneContact()
	{
		P.alpha_S = 300;
		shapelets = touchTable({0.3, -0.2, 0.4, P.leg_width, P.texture}, P, {{0, 0, 0.004}});
		broad.acceptance = inference::AcceptanceRule::ReversibleJump;
		broad.proposals = inference::Proposals::Broad;
	}
	model::ModelParams P;
	std::vector<obs::Shapelet> shapelets;
	inference::SamplerParams broad;
	inference::Acceptance acceptance{inference::AcceptanceRule::ReversibleJump};
};

/** The model's probability that shapelet 0 of `shapelets` has a free leg of its own (against
 *  none), its centre within `radius` of the contact, its yaw any: odds = the integral of
 *  exp(logOddsLeg) per (2 delta)^3 cell (logJoint counts each hypothesis as a cell's mass,
 *  eq. 19), by quadrature on a polar grid. */
inline double legProbability(const model::ModelParams& P, const std::vector<obs::Shapelet>& shapelets, double radius)
{
	ContextOnBoard q(P);
	q.bb.reset(shapelets);
	const obs::Shapelet& s = shapelets[0];
	model::Leg leg;
	leg.wx = leg.wy = P.leg_width, leg.texture = s.texture;
	const model::Id l = q.bb.addLeg(leg);
	q.bb.setShapeletParent(0, l);
	const int NR = 60, NPHI = 120, NYAW = 180;
	const double cell = std::pow(2 * P.delta, 3);
	double odds = 0;
	for (int i = 0; i < NR; i++)
		for (int j = 0; j < NPHI; j++)
			for (int k = 0; k < NYAW; k++)
			{
				const double r = radius * (i + 0.5) / NR, phi = 2 * M_PI * (j + 0.5) / NPHI;
				leg.x = s.x + r * std::cos(phi), leg.y = s.y + r * std::sin(phi), leg.theta = 2 * M_PI * (k + 0.5) / NYAW;
				q.bb.setLeg(l, leg);
				odds += std::exp(model::logOddsLeg(q.bb, l)) * r * (radius / NR) * (2 * M_PI / NPHI) * (2 * M_PI / NYAW) / cell;
			}
	return odds / (1 + odds);
}

/** Three legs of a table, each refitted to two contacts on its outer faces, free; the table's
 *  birth from its canonical leg adopts all three. */
struct ThreeLegs : ContextOnBoard
{
	explicit ThreeLegs(const model::ModelParams& params) : ContextOnBoard(params)
	{
		bb.reset(touchTable(
			TRUTH, P, {{0, 0, 0.01}, {0, 1, -0.005}, {1, 1, 0.0}, {1, 2, 0.01}, {3, 0, -0.01}, {3, 3, 0.005}}));
		const int corners[3] = {0, 1, 3};
		for (int i = 0; i < 3; i++)
		{
			model::Leg leg;
			model::tableCorner(TRUTH, corners[i], P, leg.x, leg.y);
			leg.theta = TRUTH.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture;
			legs[i] = bb.addLeg(leg);
			bb.setShapeletParent(static_cast<size_t>(2 * i), legs[i]);
			bb.setShapeletParent(static_cast<size_t>(2 * i + 1), legs[i]);
			double ignored = 0;
			ctx.refitInPlace(legs[i], ignored);
		}
	}
	static constexpr model::Table TRUTH{0.2, 0.1, 0.3, 0.05, 0.7};
	model::Id legs[3] = {model::NONE, model::NONE, model::NONE};
};

/** log of the model's odds of a table over the three legs against none: the integral of
 *  exp(logJoint with the table at pose x, the legs its children) over x, per eq. 19 cell
 *  (the table and its pose's posterior moments in `moments`). */
inline double logTableOdds(const model::ModelParams& P, Moments& moments)
{
	ThreeLegs b(P);
	const double without = model::logJoint(b.bb);
	const model::Id t = b.bb.addTable(ThreeLegs::TRUTH);
	for (const model::Id l : b.legs) b.bb.setLegParent(l, t);
	const auto logp = [&](const Pose& p) {
		return logJointAt(b.bb, b.bb.table(t), p, [&](const model::Table& to) { b.bb.setTable(t, to); }) - without;
	};
	moments = quadrature(logp, poseOf(ThreeLegs::TRUTH));
	return moments.logIntegral - 3 * std::log(2 * P.delta);
}

/** Two legs on one long side of a table (corners 0 and 1), each refitted to two contacts on
 *  its outer faces, free: the table and its mirror image across them explain them equally. */
struct TwoLegs : ContextOnBoard
{
	explicit TwoLegs(const model::ModelParams& params) : ContextOnBoard(params)
	{
		bb.reset(touchTable(ThreeLegs::TRUTH, P, {{0, 0, 0.01}, {0, 1, -0.005}, {1, 1, 0.0}, {1, 2, 0.01}}));
		for (int i = 0; i < 2; i++)
		{
			model::Leg leg;
			model::tableCorner(ThreeLegs::TRUTH, i, P, leg.x, leg.y);
			leg.theta = ThreeLegs::TRUTH.theta, leg.wx = leg.wy = P.leg_width, leg.texture = P.texture;
			legs[i] = bb.addLeg(leg);
			bb.setShapeletParent(static_cast<size_t>(2 * i), legs[i]);
			bb.setShapeletParent(static_cast<size_t>(2 * i + 1), legs[i]);
			double ignored = 0;
			ctx.refitInPlace(legs[i], ignored);
		}
	}
	/** The table's mirror image across its side through corners 0 and 1. */
	static model::Table mirror(const model::ModelParams& P)
	{
		model::Table m = ThreeLegs::TRUTH;
		double x0 = 0, y0 = 0, x3 = 0, y3 = 0;  // corner 0 and the corner across the width from it
		model::tableCorner(m, 0, P, x0, y0);
		model::tableCorner(m, 3, P, x3, y3);
		m.x += x0 - x3, m.y += y0 - y3;
		return m;
	}
	model::Id legs[2] = {model::NONE, model::NONE};
};

/** log of the model's odds of `table` over the two legs (with or without an invented leg at
 *  each of its empty corners, exactly there) against no table, per eq. 19 cell of its pose. */
inline double logTwoLegOdds(const model::ModelParams& P, const model::Table& table, Moments& moments)
{
	const double without = model::logJoint(TwoLegs(P).bb);
	std::vector<std::unique_ptr<TwoLegs>> boards;  // one per set of invented legs
	std::vector<model::Id> tables;
	for (int mask = 0; mask < 4; mask++)
	{
		auto b = std::make_unique<TwoLegs>(P);
		const model::Id t = b->bb.addTable(table);
		for (const model::Id l : b->legs) b->bb.setLegParent(l, t);
		const model::CornerCounts counts = b->bb.cornerCounts(t);
		int k = 0;
		for (int c = 0; c < 4; c++)
			if (counts[static_cast<size_t>(c)] == 0 && (mask >> k++ & 1))
			{
				model::Leg leg;
				leg.wx = leg.wy = table.leg_width, leg.texture = table.texture;
				model::tableCorner(table, c, P, leg.x, leg.y);
				leg.theta = table.theta, leg.parent = t;
				b->bb.addLeg(leg);
			}
		EXPECT_EQ(k, 2);  // both legs at corners of the table, two corners empty
		boards.push_back(std::move(b)), tables.push_back(t);
	}
	const auto logp = [&](const Pose& p) {
		double sum = -std::numeric_limits<double>::infinity();
		for (size_t i = 0; i < boards.size(); i++)
		{
			model::Blackboard& bb = boards[i]->bb;
			model::Table moved = table;
			moved.x = p[0], moved.y = p[1], moved.theta = p[2];
			bb.setTable(tables[i], moved);
			for (const model::Id l : bb.legsOf(tables[i]))
				if (!bb.explains(l))
				{
					model::Leg leg = bb.leg(l);
					model::tableCorner(moved, leg.corner, P, leg.x, leg.y);
					leg.theta = moved.theta;
					bb.setLeg(l, leg);
				}
			sum = model::logSumExp(sum, model::logJoint(bb) - without);
		}
		return sum;
	};
	moments = quadrature(logp, poseOf(table), 41);
	return moments.logIntegral - 3 * std::log(2 * P.delta);
}
}  // namespace whiskermap::test
