#include <whiskermap/inference/RigidTableFit.h>
#include <whiskermap/model/Densities.h>

#include <cmath>

namespace whiskermap::inference
{
model::Table fitRigidTable(const model::LastingState& s, model::Id t, const model::ModelParams& p)
{
	// sum over its legs of eq. 7, each leg at its corner of `table`, turned with it
	auto score = [&](const model::Table& table) {
		double v = 0;
		for (const model::Id l : s.legsOf(t))
		{
			model::Leg leg = s.leg(l);
			if (leg.corner < 0) continue;
			model::tableCorner(table, leg.corner, p, leg.x, leg.y);  // eq. 6, rigid
			leg.theta = table.theta;
			if (!s.evidence(l).empty()) v += s.evidence(l).logLikelihood(leg, p);
			for (const model::Id c : s.contactsOf(l)) v += model::logShapeletGivenLeg(s.contact(c).shapelet, leg, p);
		}
		return v;
	};
	model::Table best = s.table(t);
	if (s.legsOf(t).empty()) return best;
	// Turns pivot about the legs' mean corner, so that a turn barely moves the touched legs
	// as a whole and the search's axes are nearly independent.
	model::Table origin;  // the table's frame
	origin.cls = best.cls;
	double ox = 0, oy = 0, n = 0;
	for (const model::Id l : s.legsOf(t))
	{
		if (s.leg(l).corner < 0) continue;
		double cx = 0, cy = 0;
		model::tableCorner(origin, s.leg(l).corner, p, cx, cy);
		ox += cx, oy += cy, n++;
	}
	if (n > 0) ox /= n, oy /= n;  // pivot in the table frame
	const double reach = std::hypot(p.lengthOf(best.cls), p.widthOf(best.cls)) / 2;  // a turn moves corners at most this much
	auto turned = [&](model::Table c, double d) {
		const double c0 = std::cos(c.theta), s0 = std::sin(c.theta), c1 = std::cos(c.theta + d), s1 = std::sin(c.theta + d);
		c.x += (c0 - c1) * ox - (s0 - s1) * oy;  // the pivot stays where it was
		c.y += (s0 - s1) * ox + (c0 - c1) * oy;
		c.theta += d;
		return c;
	};
	double value = score(best);
	for (double step = p.leg_width / 8; step > 1e-5; step /= 2)
		for (bool improved = true; improved;)
		{
			improved = false;
			for (int k = 0; k < 6; k++)
			{
				const double sign = k % 2 ? -1 : 1;
				model::Table c = best;
				if (k < 4)
					(k < 2 ? c.x : c.y) += sign * step;
				else
					c = turned(c, sign * step / reach);
				const double v = score(c);
				if (v > value + 1e-12) value = v, best = c, improved = true;
			}
		}
	return best;
}
}  // namespace whiskermap::inference
