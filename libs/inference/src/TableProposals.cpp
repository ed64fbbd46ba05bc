#include <whiskermap/inference/PoseFit.h>
#include <whiskermap/inference/TableProposals.h>
#include <whiskermap/model/Densities.h>
#include <whiskermap/model/Posterior.h>

#include <cmath>
#include <limits>

namespace whiskermap::inference
{
using model::Id;
using model::Leg;
using model::Table;

double removeTableAndOrphans(model::Blackboard& bb, Id table, std::vector<Id>& orphans)
{
	double logOdds = -model::logOddsTable(bb, table);
	orphans.clear();
	for (const Id l : bb.legsOf(table))
		if (!bb.explains(l)) orphans.push_back(l);
	bb.removeTable(table);
	for (const Id l : orphans)
	{
		logOdds -= model::logOddsLeg(bb, l);
		bb.removeLeg(l);
	}
	return logOdds;
}

Table tableWithLegAt(const model::ModelParams& p, const Leg& leg, int corner, double turn, int cls)
{
	Table t;
	t.theta = leg.theta + turn;
	t.cls = cls;
	t.leg_width = p.legWidthOf(cls);
	t.texture = p.textureOf(cls);
	double cx = 0, cy = 0;  // the corner of a table centred at the origin
	model::tableCorner(t, corner, p, cx, cy);
	t.x = leg.x - cx;
	t.y = leg.y - cy;
	return t;
}

void tablesForPairs(const model::Blackboard& bb, Id l, std::vector<Table>& out)
{
	for (int k = 0; k < bb.params().classCount(); k++) tablesForPairs(bb, l, k, out);
}

void tablesForPairs(const model::Blackboard& bb, Id l, int cls, std::vector<Table>& out)
{
	const model::ModelParams& p = bb.params();
	const double gate = p.parent_gate, diagonal = std::hypot(p.lengthOf(cls), p.widthOf(cls));
	Table frame = tableWithLegAt(p, bb.leg(l), 0, 0, cls);
	frame.x = frame.y = frame.theta = 0;
	double cx[4], cy[4], cornerDistance[2][4];
	model::tableCorners(frame, p, cx, cy);
	for (int a = 0; a < 2; a++)
		for (int b = 0; b < 4; b++) cornerDistance[a][b] = std::hypot(cx[a] - cx[b], cy[a] - cy[b]);
	bb.forEachLegNear(bb.leg(l).x, bb.leg(l).y, diagonal + 2 * gate, [&](Id o) {
		// A partner whose texture is more than 5 sigma from the table's costs it over 25 nats
		// (eq. 6): not worth proposing.
		if (std::abs(bb.leg(o).texture - frame.texture) > 5 * p.sigma_tau) return;
		const model::Leg* pair[2] = {&bb.leg(l), &bb.leg(o)};
		const double d = std::hypot(pair[1]->x - pair[0]->x, pair[1]->y - pair[0]->y);
		// l at corner 0 or 1, o at another: with the 180 deg symmetry these are all the tables
		// (each corner distance twice: the table and its mirror image across the pair).
		for (int a = 0; a < 2 && o != l; a++)
			for (int b = 0; b < 4; b++)
			{
				const int corners[2] = {a, b};
				if (b != a && std::abs(cornerDistance[a][b] - d) <= 2 * gate)
					out.push_back(fitTable(p, frame, pair, corners, 2));
			}
	});
}

size_t adoptable(const model::Blackboard& bb, const Table& t, Id l, std::vector<Id>& out)
{
	const model::ModelParams& p = bb.params();
	double cx[4], cy[4], d2 = 0;
	model::tableCorners(t, p, cx, cy);
	const int own = model::nearestCorner(cx, cy, bb.leg(l).x, bb.leg(l).y, d2);
	out.clear();
	// The nearest leg within the gate of each empty corner (corners are far more than two
	// gates apart; at very noisy readings the gate is wide enough to hold a neighbour's leg).
	for (int c = 0; c < 4; c++)
	{
		if (c == own) continue;
		Id nearest = model::NONE;
		double best = std::numeric_limits<double>::infinity();
		bb.forEachLegNear(cx[c], cy[c], p.parent_gate, [&](Id o) {
			const double d2c = (bb.leg(o).x - cx[c]) * (bb.leg(o).x - cx[c]) + (bb.leg(o).y - cy[c]) * (bb.leg(o).y - cy[c]);
			if (o != l && d2c < best) best = d2c, nearest = o;
		});
		if (nearest != model::NONE) out.push_back(nearest);
	}
	return out.size();
}
}  // namespace whiskermap::inference
