#pragma once
#include <gtest/gtest.h>
#include <whiskermap/inference/Acceptance.h>
#include <whiskermap/inference/moves/GridScan.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/inference/moves/PoseGrid.h>

#include "SyntheticTable.h"

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace whiskermap::test
{
/** `name` from the environment, else `release`, or `sanitized` in a sanitizer build: the
 *  exactness tests' length (doc/sampler.md). */
inline long lengthFromEnv(const char* name, long release, [[maybe_unused]] long sanitized)
{
	if (const char* env = std::getenv(name)) return std::atol(env);
#if defined(__SANITIZE_ADDRESS__)
	return sanitized;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
	return sanitized;
#endif
#endif
	return release;
}

/** The grid problem of the sampler's exactness tests (doc/sampler.md, "Random scan on a pose
 *  grid"): 3 contacts on two legs of a known table, a grid of 3 leg poses (the two true
 *  legs and one 8 mm off) and 2 table poses (the true one and one 1 cm off). The model is
 *  flattened (cells, missing legs, priors) so that the posterior spreads over many states
 *  and the chain mixes in ~50 steps. */
struct GridProblem
{
	model::ModelParams P;
	inference::SamplerParams S;
	std::vector<obs::Shapelet> shapelets;
	inference::moves::PoseGrid grid;

	GridProblem()
	{
		P.delta = 0.5, P.epsilon = 0.5, P.c_T = 1, P.c_S = 1e6, P.c_L = 1, P.alpha_L = 10;
		const model::Table t{0, 0, 0.3, P.leg_width, P.texture};
		shapelets = test::touchTable(t, P, {{0, 0, 0}, {0, 1, 0.01}, {1, 2, 0}});
		for (const int corner : {0, 1})
		{
			model::Leg l;
			model::tableCorner(t, corner, P, l.x, l.y);
			l.theta = t.theta, l.wx = l.wy = P.leg_width, l.texture = P.texture;
			grid.legs.push_back(l);
		}
		grid.legs.push_back(grid.legs[0]);
		grid.legs.back().x += 0.008;
		grid.tables = {t, t};
		grid.tables[1].x += 0.01;
	}
};

/** The state as a string: the table's grid index (or -), then per shapelet the rank of its
 *  leg in order of first appearance (or -), then per leg its grid index and parent flag. */
inline std::string gridStateKey(const model::Blackboard& bb, const inference::moves::PoseGrid& grid)
{
	std::string key = "T";
	for (model::Id t = 0; t < bb.tableIdBound(); t++)
		if (bb.hasTable(t)) key += std::to_string(grid.tableIndex(bb.table(t)));
	key += " S";
	std::vector<model::Id> order;
	for (size_t s = 0; s < bb.shapelets().size(); s++)
	{
		const model::Id l = bb.shapeletParent(s);
		if (l == model::NONE)
		{
			key += '-';
			continue;
		}
		size_t r = 0;
		while (r < order.size() && order[r] != l) r++;
		if (r == order.size()) order.push_back(l);
		key += std::to_string(r);
	}
	key += " L" + std::to_string(bb.legCount() - order.size());  // legs explaining nothing (none here)
	for (const model::Id l : order) key += " g" + std::to_string(grid.legIndex(bb.leg(l))) + (bb.leg(l).parent == model::NONE ? "f" : "p");
	return key;
}

/** Calls f(board) for every state of the grid problem on shapelets `y` (the board is
 *  reused): no table or one at a grid pose; every assignment of the shapelets to none or to
 *  legs (each leg explaining at least one), each leg at a grid pose, free or linked to the
 *  table when within its gate (LegReparent::withinGate). */
template <class F>
void forEachGridState(const GridProblem& pr, const std::vector<obs::Shapelet>& y, F&& f)
{
	const size_t n = y.size(), g = pr.grid.legs.size();
	model::Blackboard bb(pr.P);
	inference::SamplerRandom rng;
	const inference::Acceptance acceptance;
	inference::moves::MoveContext ctx(bb, pr.P, pr.S, rng, acceptance);
	std::vector<int> block(n, -1);
	// Assignments of shapelets to legs (restricted growth: leg b first appears before b + 1).
	const auto visit = [&](int blocks) {
		size_t combos = 1;
		for (int b = 0; b < blocks; b++) combos *= 2 * g;
		for (int t = -1; t < static_cast<int>(pr.grid.tables.size()); t++)
			for (size_t c = 0; c < combos; c++)
			{
				bb.reset(y);
				const model::Id table = t < 0 ? model::NONE : bb.addTable(pr.grid.tables[static_cast<size_t>(t)]);
				bool valid = true;
				std::vector<model::Id> legs;
				for (size_t b = 0, code = c; b < static_cast<size_t>(blocks); b++, code /= 2 * g)
				{
					legs.push_back(bb.addLeg(pr.grid.legs[code % (2 * g) / 2]));
					if (code % 2 == 0) continue;
					valid = valid && table != model::NONE &&
							inference::moves::LegReparent::withinGate(ctx, legs.back(), table);
					if (valid) bb.setLegParent(legs.back(), table);
				}
				if (!valid) continue;
				for (size_t s = 0; s < n; s++)
					if (block[s] >= 0) bb.setShapeletParent(s, legs[static_cast<size_t>(block[s])]);
				f(static_cast<const model::Blackboard&>(bb));
			}
	};
	const auto assign = [&](auto& self, size_t s, int blocks) -> void {
		if (s == n) return visit(blocks);
		for (int b = -1; b <= blocks; b++)
		{
			block[s] = b;
			self(self, s + 1, std::max(blocks, b + 1));
		}
	};
	assign(assign, 0, 0);
}

/** `to` gets the hypotheses and links of `from` on shapelets `y` (same count). */
inline void withShapelets(const model::Blackboard& from, const std::vector<obs::Shapelet>& y, model::Blackboard& to)
{
	to.reset(y);
	std::vector<model::Id> tables(from.tableIdBound(), model::NONE), legs(from.legIdBound(), model::NONE);
	for (model::Id t = 0; t < from.tableIdBound(); t++)
		if (from.hasTable(t)) tables[t] = to.addTable(from.table(t));
	for (model::Id l = 0; l < from.legIdBound(); l++)
		if (from.hasLeg(l))
		{
			model::Leg leg = from.leg(l);
			leg.parent = leg.parent == model::NONE ? model::NONE : tables[leg.parent];
			legs[l] = to.addLeg(leg);
		}
	for (size_t s = 0; s < y.size(); s++)
		if (from.shapeletParent(s) != model::NONE) to.setShapeletParent(s, legs[from.shapeletParent(s)]);
}

/** The grid scan with one move deliberately wrong: the grid leg death reports logReverse = 0
 *  (its reverse density, the grid birth's -log N - log |G|, dropped). The exactness tests
 *  must fail on it. */
inline inference::RandomScan gridScanWithoutDeathReverse(const inference::moves::PoseGrid& grid)
{
	inference::RandomScan scan = inference::moves::gridScan(grid);
	inference::ScanMove& death = scan.moves()[1];
	EXPECT_EQ(death.name, "grid leg death");
	death.propose = [inner = death.propose](inference::moves::MoveContext& c) {
		auto p = inner(c);
		if (p) p->logReverse = 0;
		return p;
	};
	return scan;
}
}  // namespace whiskermap::test
