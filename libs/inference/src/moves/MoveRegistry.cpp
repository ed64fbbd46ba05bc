#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/moves/ContactExchange.h>
#include <whiskermap/inference/moves/LegBirthDeath.h>
#include <whiskermap/inference/moves/LegRefit.h>
#include <whiskermap/inference/moves/LegReparent.h>
#include <whiskermap/inference/moves/MoveRegistry.h>
#include <whiskermap/inference/moves/ShapeletLink.h>
#include <whiskermap/inference/moves/SlidingTableBirth.h>
#include <whiskermap/inference/moves/SplitMerge.h>
#include <whiskermap/inference/moves/TableBirthDeath.h>
#include <whiskermap/inference/moves/TableClassSwitch.h>
#include <whiskermap/inference/moves/TableLegFit.h>
#include <whiskermap/inference/moves/TableRefit.h>
#include <whiskermap/inference/moves/WallBirthDeath.h>
#include <whiskermap/inference/moves/WallLink.h>
#include <whiskermap/inference/moves/WallMerge.h>
#include <whiskermap/inference/moves/WallRefit.h>
#include <whiskermap/model/Densities.h>

#include <memory>

namespace whiskermap::inference::moves
{
using model::Id;

namespace
{
/** Proposes with `propose` (nullopt: nothing proposed) and lets the sampler judge it. */
template <class M, class Propose>
void tryMove(MoveContext& ctx, M& move, Propose&& propose)
{
	if (const std::optional<Proposal> p = propose()) ctx.judge(move, *p);
}

/** Priming, Q(pa(S)): with prob. existing_leg_probability a link to a leg near s (if any),
 *  else a new leg for s. */
struct Priming
{
	ShapeletLink link;
	LegBirthDeath birth;
	std::vector<Id> legs;

	void operator()(MoveContext& ctx, Id s)
	{
		const auto shapelet = static_cast<size_t>(s);
		ctx.legsNearShapelet(shapelet, legs);
		if (!legs.empty() && ctx.rng.uniform() < ctx.sp.existing_leg_probability)
			ctx.judge(link, link.link(ctx, shapelet, legs[ctx.rng.pick(legs.size())], Move::Priming));
		else
			ctx.judge(birth, birth.birthFor(ctx, shapelet));
	}
};

/** Q(ch(L) | L): half the time (if L keeps something) a split of one of its contacts; else
 *  with prob. merge_probability a merge with a nearby leg; else a link of a nearby shapelet.
 *  The polish offers the split, every merge and a link. */
struct LegChild
{
	SplitMerge splitMerge;
	ShapeletLink link;
	std::vector<Id> candidates, mergeable;

	void operator()(MoveContext& ctx, Id l)
	{
		const model::Blackboard& bb = ctx.bb;
		candidates = bb.shapeletsOf(l);
		// A split needs a contact to leave and something to stay: another contact or folded evidence.
		if (!candidates.empty() && candidates.size() + !bb.evidence(l).empty() >= 2 &&
			(ctx.greedy() || ctx.rng.uniform() < 0.5))
		{
			const auto s = static_cast<size_t>(candidates[ctx.rng.pick(candidates.size())]);
			ctx.judge(splitMerge, splitMerge.split(ctx, s));
			if (!ctx.greedy()) return;
		}
		if (ctx.greedy() || ctx.rng.uniform() < ctx.sp.merge_probability)
		{
			SplitMerge::candidates(ctx, l, mergeable);
			if (ctx.greedy())
			{
				for (size_t i = 0; i < mergeable.size() && bb.hasLeg(l); i++)
					if (bb.hasLeg(mergeable[i])) tryMove(ctx, splitMerge, [&] { return splitMerge.merge(ctx, l, mergeable[i]); });
				if (!bb.hasLeg(l)) return;
			}
			else if (!mergeable.empty())
			{
				const Id other = mergeable[ctx.rng.pick(mergeable.size())];
				tryMove(ctx, splitMerge, [&] { return splitMerge.merge(ctx, l, other); });
				return;
			}
		}
		const model::OrientedRect r = model::legRect(bb.leg(l));
		candidates.clear();
		for (size_t s = 0; s < bb.shapelets().size(); s++)
			if (bb.shapeletParent(s) != l && bb.shapeletWall(s) == model::NONE &&
				!r.fartherThan(bb.shapelets()[s].x, bb.shapelets()[s].y, ctx.mp.parent_gate) &&
				r.perimeter(bb.shapelets()[s].x, bb.shapelets()[s].y).distance <= ctx.mp.parent_gate)
				candidates.push_back(static_cast<Id>(s));
		if (candidates.empty()) return;
		const auto s = static_cast<size_t>(candidates[ctx.rng.pick(candidates.size())]);
		ctx.judge(link, link.link(ctx, s, l, Move::Child));
	}
};
/** Q(ch(W) | W): half the time a link of a nearby shapelet to w, else a release of one of
 *  its shapelets; the polish offers every link. */
struct WallChild
{
	std::shared_ptr<WallLink> move = std::make_shared<WallLink>();

	void operator()(MoveContext& ctx, Id w)
	{
		if (ctx.greedy()) return move->polish(ctx, w);
		if (ctx.rng.uniform() < 0.5) tryMove(ctx, *move, [&] { return move->link(ctx, w); });
		else tryMove(ctx, *move, [&] { return move->release(ctx, w); });
	}
};

/** A merge of w with a collinear wall touching it, drawn uniformly; the polish offers each. */
struct WallJoin
{
	std::shared_ptr<WallMerge> move;
	std::vector<Id> others;

	void operator()(MoveContext& ctx, Id w)
	{
		WallMerge::candidates(ctx.bb, w, others);
		if (others.empty()) return;
		if (!ctx.greedy())
			return (void)tryMove(ctx, *move, [&] { return move->merge(ctx, w, others[ctx.rng.pick(others.size())]); });
		for (const Id v : others)
			if (ctx.bb.hasWall(w) && ctx.bb.hasWall(v)) tryMove(ctx, *move, [&] { return move->merge(ctx, w, v); });
	}
};

/** The polish's sliding tables for leg l: each of its pair tables until one is accepted. */
struct SlidingTableForLeg
{
	std::shared_ptr<SlidingTableBirth> move;
	std::vector<model::Table> tables;

	void operator()(MoveContext& ctx, Id l)
	{
		// Pair tables fitted to their legs: data-driven (not broad); the per-pose step's only
		// (in the lasting map it cost tactile SLAM its track: doc/sampler.md, "Polish moves").
		if (ctx.broad() || ctx.annealing) return;
		SlidingTableBirth::candidates(ctx, l, tables);
		for (const model::Table& t : tables)
			if (ctx.bb.hasLeg(l) && ctx.bb.leg(l).parent == model::NONE) ctx.judge(*move, move->propose(ctx, l, t));
	}
};

/** The polish's contact exchanges from leg l: each of its contacts to each other leg whose
 *  perimeter is within the parent gate of it. */
struct ExchangeFromLeg
{
	std::shared_ptr<ContactExchange> move;
	std::vector<Id> own, legs;

	void operator()(MoveContext& ctx, Id l)
	{
		if (ctx.broad() || ctx.annealing) return;  // both legs refitted to their contacts; the step's only
		own = ctx.bb.shapeletsOf(l);
		for (const Id s : own)
		{
			ctx.legsNearShapelet(static_cast<size_t>(s), legs);
			for (const Id to : legs)
				if (ctx.bb.shapeletParent(static_cast<size_t>(s)) == l)
					tryMove(ctx, *move, [&] { return move->propose(ctx, static_cast<size_t>(s), to); });
		}
	}
};

/** The wall birth for leg l: seeded at one of its shapelets, drawn uniformly. */
struct WallForLeg
{
	std::shared_ptr<WallBirthDeath> move;

	void operator()(MoveContext& ctx, Id l)
	{
		const std::vector<Id>& own = ctx.bb.shapeletsOf(l);
		if (own.empty()) return;
		const auto s = static_cast<size_t>(own[ctx.rng.pick(own.size())]);
		tryMove(ctx, *move, [&] { return move->birth(ctx, s); });
	}
};
}  // namespace

MoveRegistry::MoveRegistry(const model::ModelParams& p)
{
	const auto legs = std::make_shared<LegBirthDeath>();
	const auto tables = std::make_shared<TableBirthDeath>(p);
	const auto legRefit = std::make_shared<LegRefit>();
	const auto tableRefit = std::make_shared<TableRefit>();
	const auto reparent = std::make_shared<LegReparent>();
	const auto classSwitch = std::make_shared<TableClassSwitch>();
	// Name, target, slot, offers per polish sweep, visit; a sweep offers them in this order.
	m_entries = {
		{"priming", Target::Shapelet, Slot::Always, 1, Priming{}},
		{"table death", Target::Table, Slot::Death, 1,
		 [=](MoveContext& c, Id t) { c.judge(*tables, tables->death(c, t)); }},
		{"table child", Target::Table, Slot::Child, 3,
		 [=](MoveContext& c, Id t) { tryMove(c, *legs, [&] { return legs->birthAtCorner(c, t); }); }},
		{"table refit", Target::Table, Slot::Refit, 1,
		 [=](MoveContext& c, Id t) { tryMove(c, *tableRefit, [&] { return tableRefit->propose(c, t); }); }},
		{"table class", Target::Table, Slot::Refit, 1,
		 [=](MoveContext& c, Id t) { tryMove(c, *classSwitch, [&] { return classSwitch->propose(c, t); }); }},
		{"leg death", Target::Leg, Slot::Death, 1,
		 [=](MoveContext& c, Id l) { tryMove(c, *legs, [&] { return legs->death(c, l); }); }},
		{"leg reparent", Target::Leg, Slot::NewParent, 1,
		 [=](MoveContext& c, Id l) { tryMove(c, *reparent, [&] { return reparent->propose(c, l); }); }},
		{"leg child", Target::Leg, Slot::Child, 1, LegChild{}},
		{"leg refit", Target::Leg, Slot::Refit, 1,
		 [=](MoveContext& c, Id l) { tryMove(c, *legRefit, [&] { return legRefit->propose(c, l); }); }},
		{"table for leg", Target::Leg, Slot::Parent, 1,
		 [=](MoveContext& c, Id l) { c.judge(*tables, tables->birth(c, l)); }},
		{"contact exchange", Target::Leg, Slot::PolishLastSweep, 1, ExchangeFromLeg{std::make_shared<ContactExchange>(), {}, {}}},
		{"sliding table for leg", Target::Leg, Slot::PolishButLast, 1, SlidingTableForLeg{std::make_shared<SlidingTableBirth>(p), {}}},
		// Greedy compass search of the leg's pose on its exact local log-odds (PoseFit.h); an
		// optimiser, not a proposal: the broad baseline goes without it.
		{"leg pose search", Target::Leg, Slot::PolishLastSweep, 1,
		 [](MoveContext& c, Id l) {
			 if (c.broad()) return;
			 const bool better = searchLegPose(c.bb, l, 1e-9, &c.result->poseEvaluations) > 0;
			 c.count(Move::Refit, better);
			 if (better) c.changed();
		 }},
	};
	if (p.size_moves)  // without size moves every table has its class's size, draw for draw as before
	{
		const auto resize = std::make_shared<TableRefit>(true);
		m_entries.push_back({"table resize", Target::Table, Slot::Refit, 1,
							 [=](MoveContext& c, Id t) { tryMove(c, *resize, [&] { return resize->propose(c, t); }); }});
		if (p.legsVary())  // eq. 26: without a leg spread every table keeps its class's legs, draw for draw
		{
			const auto legFit = std::make_shared<TableLegFit>();
			m_entries.push_back({"table legs", Target::Table, Slot::Refit, 1,
								 [=](MoveContext& c, Id t) { tryMove(c, *legFit, [&] { return legFit->propose(c, t); }); }});
		}
	}
	if (!p.walls) return;  // without walls the sweep is the paper's, draw for draw
	const auto walls = std::make_shared<WallBirthDeath>(p);
	const auto wallRefit = std::make_shared<WallRefit>();
	m_entries.push_back({"wall for leg", Target::Leg, Slot::Parent, 1, WallForLeg{walls}});
	m_entries.push_back({"wall death", Target::Wall, Slot::Death, 1,
						 [=](MoveContext& c, Id w) { tryMove(c, *walls, [&] { return walls->death(c, w); }); }});
	m_entries.push_back({"wall child", Target::Wall, Slot::Child, 1, WallChild{}});
	m_entries.push_back({"wall refit", Target::Wall, Slot::Refit, 1,
						 [=](MoveContext& c, Id w) { tryMove(c, *wallRefit, [&] { return wallRefit->propose(c, w); }); }});
	m_entries.push_back({"wall merge", Target::Wall, Slot::Parent, 1, WallJoin{std::make_shared<WallMerge>(p), {}}});
}
}  // namespace whiskermap::inference::moves
