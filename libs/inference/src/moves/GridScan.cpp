#include <whiskermap/inference/moves/FixedPoseLink.h>
#include <whiskermap/inference/moves/GridBirthDeath.h>
#include <whiskermap/inference/moves/GridScan.h>
#include <whiskermap/inference/moves/GridShift.h>
#include <whiskermap/inference/moves/LegReparent.h>

#include <cmath>
#include <memory>

namespace whiskermap::inference::moves
{
RandomScan gridScan(const PoseGrid& grid)
{
	const auto births = std::make_shared<GridBirthDeath>(grid);
	const auto link = std::make_shared<FixedPoseLink>();
	const auto reparent = std::make_shared<LegReparent>();
	const auto shift = std::make_shared<GridShift>(grid);
	const auto finishBirths = [=](MoveContext& c, bool yes) { births->finish(c, yes); };
	RandomScan scan;
	// Name, weight, index of the reverse, propose, finish; a move and its reverse together.
	scan.add({"grid leg birth", 1, 1, [=](MoveContext& c) { return births->legBirth(c); }, finishBirths});
	scan.add({"grid leg death", 2, 0, [=](MoveContext& c) { return births->legDeath(c); }, finishBirths});
	scan.add({"grid table birth", 1, 3, [=](MoveContext& c) { return births->tableBirth(c); }, finishBirths});
	scan.add({"grid table death", 2, 2, [=](MoveContext& c) { return births->tableDeath(c); }, finishBirths});
	scan.add({"fixed-pose link", 2, 4, [=](MoveContext& c) { return link->propose(c); },
			  [=](MoveContext& c, bool yes) { link->finish(c, yes); }});
	// A leg drawn uniformly (the same number of legs before and after), then LegReparent.
	scan.add({"leg reparent", 1, 5,
			  [=](MoveContext& c) -> std::optional<Proposal> {
				  const size_t legs = c.bb.legCount();
				  if (legs == 0) return std::nullopt;
				  std::optional<Proposal> p = reparent->propose(c, nthLeg(c.bb, c.rng.pick(legs)));
				  if (p) p->logForward -= std::log(static_cast<double>(legs)), p->logReverse -= std::log(static_cast<double>(legs));
				  return p;
			  },
			  [=](MoveContext& c, bool yes) { reparent->finish(c, yes); }});
	const auto finishShift = [=](MoveContext& c, bool yes) { shift->finish(c, yes); };
	scan.add({"grid table shift", 1, 6, [=](MoveContext& c) { return shift->table(c); }, finishShift});
	scan.add({"grid leg shift", 1, 7, [=](MoveContext& c) { return shift->leg(c); }, finishShift});
	return scan;
}
}  // namespace whiskermap::inference::moves
