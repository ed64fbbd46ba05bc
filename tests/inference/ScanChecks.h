#pragma once
// Checks on a random scan's moves, shared by the tests of the exact chains
// (StationaryDistribution_unittest, ReversibleJumpCells_unittest).
#include <gtest/gtest.h>
#include <whiskermap/inference/RandomScan.h>
#include <whiskermap/model/Posterior.h>

#include <memory>

namespace whiskermap::test
{
/** Wraps every move of `scan` so that each accepted proposal's logTarget is checked against
 *  the change of logJoint itself (1e-7), and each rejected one leaves logJoint as it was. */
inline void checkTargets(inference::RandomScan& scan)
{
	for (inference::ScanMove& m : scan.moves())
	{
		const auto before = std::make_shared<double>(0), target = std::make_shared<double>(0);
		m.propose = [=, inner = m.propose](inference::moves::MoveContext& c) {
			*before = model::logJoint(c.bb);
			auto p = inner(c);
			if (p) *target = p->logTarget;
			return p;
		};
		m.finish = [=, inner = m.finish, name = m.name](inference::moves::MoveContext& c, bool yes) {
			inner(c, yes);
			EXPECT_NEAR(model::logJoint(c.bb) - *before, yes ? *target : 0.0, 1e-7) << name << (yes ? " accepted" : " rejected");
		};
	}
}
}  // namespace whiskermap::test
