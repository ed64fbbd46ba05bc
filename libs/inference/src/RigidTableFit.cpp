#include <whiskermap/inference/FiniteDifferences.h>
#include <whiskermap/inference/RigidTableFit.h>
#include <whiskermap/model/Densities.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>

namespace whiskermap::inference
{
double rigidTableScore(const model::LastingState& s, model::Id t, const model::Table& table, const model::ModelParams& p)
{
	double v = 0;
	for (const model::Id l : s.legsOf(t))
	{
		model::Leg leg = s.leg(l);
		if (leg.corner < 0) continue;
		model::tableCorner(table, leg.corner, p, leg.x, leg.y);  // eq. 6, rigid
		leg.theta = table.theta;
		if (!s.evidence(l).empty()) v += s.evidence(l).logLikelihood(leg, p);  // eq. 7, folded
		for (const model::Id c : s.contactsOf(l)) v += model::logShapeletGivenLeg(s.shapelet(c), leg, p);  // eq. 7
	}
	return v;
}

model::Table fitRigidTable(const model::LastingState& s, model::Id t, const model::ModelParams& p)
{
	const auto score = [&](const model::Table& table) { return rigidTableScore(s, t, table, p); };
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
	const double reach = std::hypot(p.lengthOf(best), p.widthOf(best)) / 2;  // a turn moves corners at most this much
	auto turned = [&](model::Table c, double d) {
		const double c0 = std::cos(c.theta), s0 = std::sin(c.theta), c1 = std::cos(c.theta + d), s1 = std::sin(c.theta + d);
		c.x += (c0 - c1) * ox - (s0 - s1) * oy;  // the pivot stays where it was
		c.y += (s0 - s1) * ox + (c0 - c1) * oy;
		c.theta += d;
		return c;
	};
	// The pose as a point u = (x, y, reach * yaw turn about the pivot), all in metres.
	auto at = [&](const model::Table& base, const Eigen::Vector3d& u) {
		model::Table c = turned(base, u[2] / reach);
		c.x += u[0], c.y += u[1];
		return c;
	};
	double value = score(best);
	// Newton steps on the quadratic through 10 scores around the pose (the score is a sum of
	// quadratics, eq. 7, while no contact changes face): gradient and Hessian by differences.
	constexpr double h = 1e-4;
	for (int it = 0; it < 4; it++)
	{
		Eigen::Vector3d g;
		Eigen::Matrix3d H;
		finiteDifferences([&](const Eigen::Vector3d& u) { return score(at(best, u)); }, value, h, g, H);
		const Eigen::LDLT<Eigen::Matrix3d> ldlt(-H);
		if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) break;  // not a maximum nearby: search only
		Eigen::Vector3d u = ldlt.solve(g);
		if (!u.allFinite()) break;
		if (u.norm() > p.leg_width) u *= p.leg_width / u.norm();  // trust region: a leg width
		const model::Table c = at(best, u);
		const double v = score(c);
		if (!(v > value)) break;
		value = v, best = c;
		if (u.norm() < 1e-5) return best;  // converged: the step is below the search's resolution
	}
	// Where the quadratic does not hold: a compass search, down to 0.01 mm at the corners.
	for (double step = p.leg_width / 8; step > 1e-5; step /= 2)
		for (bool improved = true; improved;)
		{
			improved = false;
			for (int k = 0; k < 6; k++)
			{
				Eigen::Vector3d u = Eigen::Vector3d::Zero();
				u[k / 2] = k % 2 ? -step : step;
				const model::Table c = at(best, u);
				const double v = score(c);
				if (v > value + 1e-12) value = v, best = c, improved = true;
			}
		}
	return best;
}
}  // namespace whiskermap::inference
