#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/inference/moves/LibraryScan.h>
#include <whiskermap/inference/moves/PoseGrid.h>
#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/inference/moves/SplitMerge.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/inference/moves/TableRefit.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace whiskermap::inference::moves
{
using model::Id;
using model::NONE;

namespace
{
constexpr double NO_REVERSE = -std::numeric_limits<double>::infinity();
double logCount(size_t n) { return std::log(static_cast<double>(n)); }

/** Adds `forward` and `reverse` (the target draws' log probabilities) to a proposal; a
 *  reverse of -inf stays -inf. */
std::optional<Proposal> withDraws(std::optional<Proposal> p, double forward, double reverse)
{
	if (p) p->logForward += forward, p->logReverse += reverse;
	return p;
}

template <class M>
std::function<void(MoveContext&, bool)> finisher(const std::shared_ptr<M>& move)
{
	return [move](MoveContext& c, bool yes) { move->finish(c, yes); };
}

/** A self-reverse move of one hypothesis drawn uniformly among `count` of its kind. */
template <class Pick, class Propose>
std::function<std::optional<Proposal>(MoveContext&)> onUniform(Pick pick, Propose propose)
{
	return [=](MoveContext& c) -> std::optional<Proposal> {
		const auto [n, id] = pick(c);
		if (n == 0) return std::nullopt;
		return withDraws(propose(c, id), -logCount(n), -logCount(n));
	};
}
/** True if leg l explains something besides one of its shapelets. */
bool keepsSomething(const model::Blackboard& bb, Id l) { return bb.shapeletsOf(l).size() + !bb.evidence(l).empty() >= 2; }
/** A shapelet drawn uniformly among all N: N, the shapelet and its leg (NONE: it has none). */
struct ShapeletOnLeg
{
	size_t n = 0, s = 0;
	Id leg = NONE;
};
ShapeletOnLeg anyShapelet(MoveContext& c)
{
	ShapeletOnLeg out;
	out.n = c.bb.shapelets().size();
	if (out.n == 0) return out;
	out.s = c.rng.pick(out.n);
	out.leg = c.bb.shapeletParent(out.s);
	return out;
}
/** A leg (table) drawn uniformly among all: their number and its id (NONE if there is none). */
std::pair<size_t, Id> anyLeg(MoveContext& c)
{
	const size_t n = c.bb.legCount();
	return {n, n ? nthLeg(c.bb, c.rng.pick(n)) : NONE};
}
std::pair<size_t, Id> anyTable(MoveContext& c)
{
	const size_t n = c.bb.tableCount();
	return {n, n ? nthTable(c.bb, c.rng.pick(n)) : NONE};
}
/** A self-reverse move of a leg drawn uniformly, proposing nothing on a leg that explains
 *  nothing (the scan keeps those exactly at their corners, where the corner births put them). */
template <class Propose>
std::function<std::optional<Proposal>(MoveContext&)> onExplainingLeg(Propose propose)
{
	return onUniform(anyLeg, [=](MoveContext& c, Id l) -> std::optional<Proposal> {
		if (!c.bb.explains(l)) return std::nullopt;
		return propose(c, l);
	});
}
}  // namespace

RandomScan libraryScan(const model::ModelParams& params)
{
	const auto legs = std::make_shared<LegBirthDeath>();
	const auto tables = std::make_shared<TableBirthDeath>(params);
	const auto link = std::make_shared<ShapeletLink>();
	const auto splitMerge = std::make_shared<SplitMerge>();
	const auto legRefit = std::make_shared<LegRefit>();
	const auto tableRefit = std::make_shared<TableRefit>();
	const auto reparent = std::make_shared<LegReparent>();
	const auto near = std::make_shared<std::vector<Id>>();
	RandomScan scan;
	// Name, weight, index of the reverse, propose, finish; a move and its reverse together.
	scan.add({"leg birth", 1, 1,
			  [=](MoveContext& c) -> std::optional<Proposal> {
				  const size_t n = c.bb.shapelets().size(), tablesNow = c.bb.tableCount();
				  std::optional<Proposal> p;
				  double forward = std::log(0.5);
				  if (c.rng.uniform() < 0.5)  // a free leg for an unexplained shapelet
				  {
					  const size_t s = n ? c.rng.pick(n) : 0;
					  if (n == 0 || c.bb.explained(s)) return std::nullopt;
					  p = legs->birthFor(c, s), forward -= logCount(n);
				  }
				  else  // the missing leg at an empty corner of a table
				  {
					  if (tablesNow == 0) return std::nullopt;
					  p = legs->birthAtCorner(c, nthTable(c.bb, c.rng.pick(tablesNow))), forward -= logCount(tablesNow);
				  }
				  return withDraws(std::move(p), forward, -logCount(c.bb.legCount()));  // the death draws it among all legs
			  },
			  finisher(legs)});
	scan.add({"leg death", 1, 0,
			  [=](MoveContext& c) -> std::optional<Proposal> {
				  const auto [n, l] = anyLeg(c);
				  if (n == 0) return std::nullopt;
				  const bool free = c.bb.leg(l).parent == NONE;
				  // The reverse birth: half the time, its shapelet among all (free leg) or its
				  // table among all (a corner's leg).
				  const double reverse =
					  std::log(0.5) - (free ? logCount(c.bb.shapelets().size()) : logCount(c.bb.tableCount()));
				  return withDraws(legs->death(c, l), -logCount(n), reverse);
			  },
			  finisher(legs)});
	// Table birth and death (reverse indices: the pair's other), plain and completed.
	const auto tablePair = [&](const std::shared_ptr<TableBirthDeath>& move, const char* birth, const char* death) {
		const size_t at = scan.moves().size();
		scan.add({birth, 1, at + 1,
				  [=](MoveContext& c) -> std::optional<Proposal> {
					  const auto [n, l] = anyLeg(c);
					  if (n == 0) return std::nullopt;
					  Proposal p = move->birth(c, l);
					  return withDraws(p, -logCount(n), -logCount(c.bb.tableCount()));
				  },
				  finisher(move)});
		scan.add({death, 1, at,
				  [=](MoveContext& c) -> std::optional<Proposal> {
					  const auto [n, t] = anyTable(c);
					  if (n == 0) return std::nullopt;
					  Proposal p = move->death(c, t);
					  return withDraws(p, -logCount(n), -logCount(c.bb.legCount()));  // its canonical leg among those left
				  },
				  finisher(move)});
	};
	tablePair(tables, "table birth", "table death");
	scan.add({"link", 1, 4,
			  [=](MoveContext& c) -> std::optional<Proposal> {
				  const auto [n, s, from] = anyShapelet(c);
				  if (from == NONE) return std::nullopt;  // from no leg: no reverse link
				  c.legsNearShapelet(s, *near);
				  near->erase(std::remove(near->begin(), near->end(), from), near->end());
				  if (near->empty()) return std::nullopt;
				  const size_t options = near->size();
				  const Id to = (*near)[c.rng.pick(options)];
				  if (!c.bb.explains(to) || (c.bb.leg(from).parent != NONE && !keepsSomething(c.bb, from)))
					  return std::nullopt;  // a leg that explains nothing stays exactly at its corner
				  Proposal p = link->link(c, s, to, Move::Child);
				  double reverse = NO_REVERSE;  // the link back: s among all, `from` among the legs near s but `to`
				  if (std::isfinite(p.logReverse))
				  {
					  c.legsNearShapelet(s, *near);
					  near->erase(std::remove(near->begin(), near->end(), to), near->end());
					  const bool back = std::find(near->begin(), near->end(), from) != near->end();
					  if (back) reverse = -logCount(n) - logCount(near->size());
				  }
				  return withDraws(p, -logCount(n) - logCount(options), reverse);
			  },
			  finisher(link)});
	scan.add({"split", 1, 6,
			  [=](MoveContext& c) -> std::optional<Proposal> {
				  const auto [n, s, from] = anyShapelet(c);
				  if (from == NONE) return std::nullopt;
				  Proposal p = splitMerge->split(c, s);
				  double reverse = NO_REVERSE;  // the merge: `from` among all legs, then the new leg among its candidates
				  if (std::isfinite(p.logReverse))
				  {
					  SplitMerge::candidates(c, from, *near);
					  const bool back = std::find(near->begin(), near->end(), c.bb.shapeletParent(s)) != near->end();
					  if (back) reverse = -logCount(c.bb.legCount()) - logCount(near->size());
				  }
				  return withDraws(p, -logCount(n), reverse);
			  },
			  finisher(splitMerge)});
	scan.add({"merge", 1, 5,
			  [=](MoveContext& c) -> std::optional<Proposal> {
				  const auto [n, l] = anyLeg(c);
				  if (n == 0) return std::nullopt;
				  SplitMerge::candidates(c, l, *near);
				  if (near->empty()) return std::nullopt;
				  const size_t options = near->size();
				  const Id other = (*near)[c.rng.pick(options)];
				  // The split: other's one contact among all shapelets.
				  return withDraws(splitMerge->merge(c, l, other), -logCount(n) - logCount(options),
								   -logCount(c.bb.shapelets().size()));
			  },
			  finisher(splitMerge)});
	scan.add({"leg refit", 1, 7, onExplainingLeg([=](MoveContext& c, Id l) { return legRefit->propose(c, l); }),
			  finisher(legRefit)});
	scan.add({"table refit", 1, 8, onUniform(anyTable, [=](MoveContext& c, Id t) { return tableRefit->propose(c, t); }),
			  finisher(tableRefit)});
	scan.add({"leg reparent", 1, 9, onExplainingLeg([=](MoveContext& c, Id l) { return reparent->propose(c, l); }),
			  finisher(reparent)});
	const auto completed = std::make_shared<TableBirthDeath>(params, true);
	tablePair(completed, "table birth, completed", "table death, with its invented legs");
	scan.add({"table switch", 1, scan.moves().size(),
			  onUniform(anyTable, [=](MoveContext& c, Id t) { return completed->rebirth(c, t); }), finisher(completed)});
	if (params.size_moves)
	{
		const auto resize = std::make_shared<TableRefit>(true);
		scan.add({"table resize", 1, scan.moves().size(), onUniform(anyTable, [=](MoveContext& c, Id t) { return resize->propose(c, t); }),
				  finisher(resize)});
	}
	return scan;
}
}  // namespace whiskermap::inference::moves
