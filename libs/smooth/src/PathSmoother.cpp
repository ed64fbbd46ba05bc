#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/smooth/ContactFactor.h>
#include <whiskermap/smooth/DuplicateLegs.h>
#include <whiskermap/smooth/DuplicateWalls.h>
#include <whiskermap/smooth/OdometryBridge.h>
#include <whiskermap/smooth/OdometryFactor.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/smooth/SameSolidFactor.h>
#include <whiskermap/smooth/ShiftedStretch.h>
#include <whiskermap/smooth/TableShapeFactor.h>
#include <whiskermap/smooth/WallLines.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <map>

namespace whiskermap::smooth
{
namespace
{
/** The variables: the path and the group shifts. */
struct State
{
	std::vector<Eigen::Vector3d> path;
	std::vector<Eigen::Vector2d> shifts;
};

/** The problem of one round: the factors, and the variables' layout (poses 1..N-1, then the
 *  group shifts; pose 0 is fixed). */
struct Problem
{
	const std::vector<OdometryFactor>& odometry;
	std::vector<ContactFactor> contacts;
	std::vector<SameSolidFactor> same;
	std::vector<TableShapeFactor> shape;
	size_t poses, groups;
	double huber, solidSigma;
	double outlier = 0;  ///< metres: a contact farther than this from its face costs as if this far (0: no cap)

	size_t size() const { return 3 * (poses - 1) + 2 * groups; }
	long poseColumn(size_t i) const { return i == 0 ? -1 : static_cast<long>(3 * (i - 1)); }
	long groupColumn(size_t g) const { return static_cast<long>(3 * (poses - 1) + 2 * g); }

	/** Huber's loss of a whitened residual, and its IRLS weight. */
	double loss(double r, double* weight = nullptr) const
	{
		const double a = std::abs(r);
		if (weight) *weight = a <= huber ? 1 : huber / a;
		return a <= huber ? r * r : 2 * huber * a - huber * huber;
	}

	double cost(const State& s) const
	{
		const auto& x = s.path;
		const auto& d = s.shifts;
		double c = 0;
		for (size_t i = 1; i < poses; i++)
			c += odometry[i].residual(x[i - 1], x[i]).squaredNorm();  // eq. S2
		for (const auto& f : contacts)
		{
			const double l = loss(f.residual(x[f.pose], d[f.group]));  // eq. S3
			c += outlier > 0 ? std::min(l, loss(outlier / f.sigma)) : l;
		}
		for (const auto& f : same) c += f.residual(d[f.a], d[f.b]).squaredNorm();  // eqs. S4, S5
		for (const auto& f : shape) c += std::pow(f.residual(d[f.a], d[f.b]), 2);  // eq. S7
		for (const auto& g : d) c += g.squaredNorm() / (solidSigma * solidSigma);
		return c;
	}

	/** J^T W J and J^T W r at s. */
	void normalEquations(const State& s, Eigen::SparseMatrix<double>& H, Eigen::VectorXd& b) const
	{
		const auto& x = s.path;
		const auto& d = s.shifts;
		std::vector<Eigen::Triplet<double>> t;
		t.reserve(60 * poses + 25 * contacts.size() + 16 * (same.size() + shape.size()) + 4 * groups);
		b = Eigen::VectorXd::Zero(static_cast<long>(size()));
		// One residual's share, weight w: its Jacobian blocks, each (column (-1: fixed), block).
		auto add = [&](const auto& r, double w, const auto&... blocks) {
			auto row = [&](const auto& bi) {
				if (bi.first < 0) return;
				b.segment(bi.first, bi.second.cols()) += w * bi.second.transpose() * r;
				auto product = [&](const auto& bj) {
					if (bj.first < 0) return;
					const auto h = (w * bi.second.transpose() * bj.second).eval();
					for (long u = 0; u < h.rows(); u++)
						for (long v = 0; v < h.cols(); v++) t.emplace_back(bi.first + u, bj.first + v, h(u, v));
				};
				(product(blocks), ...);
			};
			(row(blocks), ...);
		};
		using std::make_pair;
		for (size_t i = 1; i < poses; i++)
		{
			Eigen::Matrix3d Ja, Jb;
			const Eigen::Vector3d r = odometry[i].residual(x[i - 1], x[i], &Ja, &Jb);
			add(r, 1, make_pair(poseColumn(i - 1), Ja), make_pair(poseColumn(i), Jb));
		}
		for (const auto& f : contacts)
		{
			Eigen::Vector3d Jx;
			Eigen::Vector2d Jd;
			const double r = f.residual(x[f.pose], d[f.group], &Jx, &Jd);
			double w;
			loss(r, &w);
			add(Eigen::Matrix<double, 1, 1>(r), w, make_pair(poseColumn(f.pose), Eigen::RowVector3d(Jx.transpose())),
				make_pair(groupColumn(f.group), Eigen::RowVector2d(Jd.transpose())));
		}
		for (const auto& f : same)
			add(f.residual(d[f.a], d[f.b]), 1, make_pair(groupColumn(f.a), Eigen::Matrix2d(f.P / f.sigma)),
				make_pair(groupColumn(f.b), Eigen::Matrix2d(-f.P / f.sigma)));
		for (const auto& f : shape)
		{
			Eigen::RowVector2d J;
			const double r = f.residual(d[f.a], d[f.b], &J);
			add(Eigen::Matrix<double, 1, 1>(r), 1, make_pair(groupColumn(f.a), J),
				make_pair(groupColumn(f.b), Eigen::RowVector2d(-J)));
		}
		const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
		for (size_t g = 0; g < groups; g++)
			add(Eigen::Vector2d(d[g] / solidSigma), 1, make_pair(groupColumn(g), Eigen::Matrix2d(I / solidSigma)));
		H.resize(static_cast<long>(size()), static_cast<long>(size()));
		H.setFromTriplets(t.begin(), t.end());
	}
};

/** The hypotheses that two mapped solids are one, from the contacts first tied: eq. S4's
 *  factors for the legs the map holds twice, in sets by the two mapped tables they pair (a table
 *  mapped twice), largest first; then eq. S5's for each wall it holds twice, one set each. */
std::vector<std::vector<SameSolidFactor>> sameSolids(
	const std::vector<world::Obstacle>& solids, const std::vector<size_t>& groupOf, size_t groups,
	const std::vector<ContactFactor>& contacts, const TSmoothParams& params)
{
	std::vector<bool> touched(solids.size(), false);
	std::vector<Eigen::Vector2d> facing(groups, Eigen::Vector2d::Zero());
	for (const auto& f : contacts) touched[f.solid] = true, facing[f.group] += f.n;
	std::map<std::pair<int, int>, std::vector<SameSolidFactor>> byTables;
	for (const auto& [i, j] : DuplicateLegs::find(solids, touched, params.duplicate_shrink, params.duplicate_distance))
		if (groupOf[i] != groupOf[j])
			byTables[std::minmax(solids[i].table, solids[j].table)].push_back(
				{groupOf[i], groupOf[j], solids[i].centre() - solids[j].centre(), params.duplicate_sigma});
	std::vector<std::vector<SameSolidFactor>> sets;
	for (auto& [tables, set] : byTables) sets.push_back(std::move(set));
	std::stable_sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
	if (params.duplicate_wall_distance > 0)
		for (const auto& w : DuplicateWalls::find(solids, groupOf, facing, params.duplicate_wall_distance))
			sets.push_back({{w.a, w.b, w.offset, params.duplicate_sigma, w.normal * w.normal.transpose()}});
	return sets;
}

/** The coordinates the factors hold (SameSolidFactor::dof). */
double dof(const std::vector<SameSolidFactor>& factors)
{
	double k = 0;
	for (const auto& f : factors) k += f.dof();
	return k;
}

/** Eq. S7's factors: every two legs of one mapped table (each in its own group) keep their
 *  distance (none when `sigma` is 0). */
std::vector<TableShapeFactor> tableShapes(
	const std::vector<world::Obstacle>& solids, const std::vector<size_t>& groupOf, double sigma)
{
	std::vector<TableShapeFactor> shapes;
	if (sigma <= 0) return shapes;
	for (size_t i = 0; i < solids.size(); i++)
		for (size_t j = i + 1; j < solids.size(); j++)
			if (solids[i].table >= 0 && solids[i].table == solids[j].table && groupOf[i] != groupOf[j])
				shapes.push_back({groupOf[i], groupOf[j], solids[i].centre() - solids[j].centre(), sigma});
	return shapes;
}

/** Ties every contact seen from x to the nearest face of the shifted solids (pb.contacts). */
void tieContacts(
	Problem& pb, const State& x, const PathSmoother::TInput& in, const std::vector<world::Obstacle>& solids,
	const std::vector<size_t>& groupOf, const TSmoothParams& params)
{
	pb.contacts.clear();
	for (size_t k = 0; k < in.contacts.size(); k++)
	{
		const auto& c = in.contacts[k];
		if (auto f = ContactFactor::associate(
				c, c.sweep, x.path[c.sweep], solids, groupOf, x.shifts, params.gate, params.normal_gate,
				params.position_floor))
			pb.contacts.push_back(*f), pb.contacts.back().contact = k;
	}
}

/** The cost of x over every contact either of two solutions tied (eq. S6): pb's own ties, and
 *  each contact only `other` tied against the face `other` tied it to, every contact's loss
 *  capped at `outlier` metres from its face (a solution that drags a solid away from its
 *  contacts unties them, which must not make it cheaper). */
double unionCost(Problem pb, const State& x, const std::vector<ContactFactor>& other, size_t contacts, double outlier)
{
	std::vector<bool> own(contacts, false);
	for (const auto& f : pb.contacts) own[f.contact] = true;
	for (const auto& f : other)
		if (!own[f.contact]) pb.contacts.push_back(f);
	pb.outlier = outlier;
	return pb.cost(x);
}

/** Rounds of tie-and-solve from x by Levenberg-Marquardt, pb.same (eq. S4) as given. Sets
 *  out's tied, costAfter, rounds and iterations; pb.contacts ends with the last round's ties. */
State solve(
	Problem& pb, State x, const PathSmoother::TInput& in, const std::vector<world::Obstacle>& solids,
	const TSmoothParams& params, PathSmoother::TResult& out)
{
	const size_t n = x.path.size(), groups = x.shifts.size();
	out.rounds = out.iterations = 0;
	for (unsigned round = 0; round < params.rounds; round++)
	{
		tieContacts(pb, x, in, solids, out.groupOf, params);
		out.tied = pb.contacts.size();
		double cost = pb.cost(x);
		out.rounds = round + 1;
		double lambda = 1e-4, firstCost = cost;
		for (unsigned it = 0; it < params.iterations; it++)
		{
			Eigen::SparseMatrix<double> H;
			Eigen::VectorXd b;
			pb.normalEquations(x, H, b);
			bool stepped = false;
			for (int tries = 0; tries < 8 && !stepped; tries++)
			{
				Eigen::SparseMatrix<double> A = H;
				for (long k = 0; k < A.rows(); k++) A.coeffRef(k, k) += lambda * (H.coeff(k, k) + 1e-9);
				Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
				if (solver.info() != Eigen::Success) { lambda *= 10; continue; }
				const Eigen::VectorXd dx = solver.solve(-b);
				State next = x;
				for (size_t i = 1; i < n; i++)
				{
					next.path[i] += dx.segment<3>(pb.poseColumn(i));
					next.path[i][2] = core::wrapToPi(next.path[i][2]);
				}
				for (size_t g = 0; g < groups; g++) next.shifts[g] += dx.segment<2>(pb.groupColumn(g));
				const double c = pb.cost(next);
				if (c < cost)
				{
					x = std::move(next);
					stepped = cost - c > 1e-9 * cost;
					cost = c;
					lambda = std::max(lambda / 10, 1e-9);
					if (!stepped) break;
				}
				else
					lambda *= 10;
			}
			out.iterations++;
			if (!stepped) break;
		}
		out.costAfter = cost;
		if (firstCost - cost < 1e-6 * firstCost) break;  // the ties no longer move the estimate
	}
	return x;
}
}  // namespace

PathSmoother::TResult PathSmoother::run(const TInput& in, const TSmoothParams& params)
{
	const size_t n = in.path.size();
	if (n == 0) throw core::Error("path smoother: empty path");
	if (in.increments.size() != n || in.covariances.size() != n)
		throw core::Error("path smoother: " + std::to_string(n) + " poses but " + std::to_string(in.increments.size()) +
						  " odometry increments");
	for (const auto& c : in.contacts)
		if (c.sweep >= n) throw core::Error("path smoother: a contact of sweep " + std::to_string(c.sweep) + " of " + std::to_string(n));
	TResult out;
	// Groups: each solid alone (the particle's table may hold its legs where the drift of the
	// moment put each), but pieces of one straight wall together (WallLines).
	size_t groups = in.solids.size();
	for (size_t i = 0; i < groups; i++) out.groupOf.push_back(i);
	auto solids = in.solids;
	if (params.wall_merge > 0) groups = WallLines::merge(solids, out.groupOf, params.wall_merge);
	std::vector<OdometryFactor> odometry;
	odometry.reserve(n);
	for (size_t i = 0; i < n; i++) odometry.emplace_back(in.increments[i], in.covariances[i]);
	const State start{in.path, std::vector<Eigen::Vector2d>(groups, Eigen::Vector2d::Zero())};
	Problem pb{odometry, {}, {}, tableShapes(solids, out.groupOf, params.table_sigma), n, groups, params.huber,
			   params.solid_sigma};
	const auto finish = [&](State x) {
		out.path = std::move(x.path), out.shifts = std::move(x.shifts);
		return out;
	};
	if (n == 1) return finish(start);
	// Odometry told exact (every increment's covariance zero): the path is its chain from the
	// known start, whatever the contacts say.
	if (std::all_of(in.covariances.begin(), in.covariances.end(), [](const Eigen::Matrix3d& c) { return c.isZero(); }))
	{
		State x = start;
		for (size_t i = 1; i < n; i++) x.path[i] = odometry[i].end(x.path[i - 1]);
		return finish(x);
	}

	// Eqs. S4 and S5's pairs, from the contacts the start ties.
	tieContacts(pb, start, in, solids, out.groupOf, params);
	const auto startTies = pb.contacts;
	const auto sets = params.duplicate_sigma > 0 ? sameSolids(solids, out.groupOf, groups, startTies, params)
												  : std::vector<std::vector<SameSolidFactor>>{};
	double all = 0;
	for (const auto& set : sets) all += dof(set);
	// The pairs are hypotheses (the copies are one leg, one wall): on a drifted map some are
	// wrong, and holding them bends the path. Each set (a table or a wall mapped twice) is kept
	// when the solution holding it with the sets kept so far costs no more than the one without,
	// over every contact either tied (unionCost), plus 2 a coordinate left apart (Akaike: a leg
	// held takes two coordinates out of the model, a wall one); largest sets first, each solved
	// from the start (eq. S6).
	State x = solve(pb, start, in, solids, params, out);
	auto ties = pb.contacts;
	std::vector<SameSolidFactor> held;  // the sets kept so far
	const auto penalty = [&](const std::vector<SameSolidFactor>& kept) { return 2 * (all - dof(kept)); };
	// A hypothesis against x: solved from y0 with `same` held, and both solutions' costs over
	// every contact either tied (unionCost; y's with `same`, x's with the sets held).
	struct Trial
	{
		State y;
		TResult r;
		std::vector<ContactFactor> ties;
		double with, without;
	};
	const auto tryFrom = [&](State y0, const std::vector<SameSolidFactor>& same) {
		pb.same = same;
		Trial t{{}, out, {}, 0, 0};
		t.y = solve(pb, std::move(y0), in, solids, params, t.r);
		t.ties = pb.contacts;
		t.with = unionCost(pb, t.y, ties, in.contacts.size(), params.gate);
		pb.same = held, pb.contacts = ties;
		t.without = unionCost(pb, x, t.ties, in.contacts.size(), params.gate);
		return t;
	};
	// A set left apart from the start is tried again from x with the stretch of path that
	// touched one copy moved, with what only that stretch touched, onto the other: the b
	// copies, then the a copies (eq. S9); the first solution that holds it is kept.
	for (const auto& set : sets)
	{
		auto trial = held;
		trial.insert(trial.end(), set.begin(), set.end());
		for (int from = 0; from < 3; from++)  // the start; x with the b copies moved; with the a copies
		{
			State y0 = from ? x : start;
			if (from && !(params.stretch_margin > 0 &&
						  ShiftedStretch::move(y0.path, y0.shifts, ties, set, from == 1, params.stretch_margin)))
				continue;
			auto t = tryFrom(std::move(y0), trial);
			if (from) out.stretchesTried++;
			if (t.with + penalty(trial) > t.without + penalty(held)) continue;  // eq. S6
			t.r.stretchesTried = out.stretchesTried, t.r.stretches = out.stretches + (from > 0);
			x = std::move(t.y), out = std::move(t.r), ties = std::move(t.ties), held = std::move(trial);
			break;
		}
	}
	// Stretches where the solution strays from the odometry (a filter locked onto the wrong
	// legs for a while): each solved again from the odometry's path across it, with the pairs
	// held, and kept when it costs less over every contact either tied (eq. S8); after a kept
	// one, the strays are found again (at most as many times as there were strays at first).
	// Two windows: a bend that comes back within the long one shows only in the short one.
	// m holds eq. S8's distances of x's windows, searched once per path x takes.
	std::vector<size_t> windows{params.bridge_window};
	if (params.bridge_short_window > 0) windows.push_back(params.bridge_short_window);
	std::vector<std::vector<double>> m;
	const auto distances = [&] {
		m.clear();
		for (const size_t w : windows) m.push_back(OdometryBridge::distances(x.path, odometry, w));
	};
	const auto strays = [&](size_t k) { return OdometryBridge::strays(m[k], windows[k], params.bridge_gate); };
	const auto candidates = [&] {
		std::vector<OdometryBridge::Stretch> found;
		for (size_t k = 0; k < windows.size(); k++)
			for (const auto& s : OdometryBridge::candidates(strays(k), windows[k], n))
				if (std::find(found.begin(), found.end(), s) == found.end()) found.push_back(s);
		return found;
	};
	distances();
	size_t most = 0;
	for (size_t k = 0; k < windows.size() && params.bridge_gate > 0; k++) most += strays(k).size();
	for (bool kept = most > 0; kept && out.bridges < most;)
	{
		kept = false;
		for (const auto& s : candidates())
		{
			auto t = tryFrom(State{OdometryBridge::bridge(x.path, odometry, s), x.shifts}, held);
			out.bridgesTried++;
			if (t.with < t.without)
			{
				t.r.bridgesTried = out.bridgesTried, t.r.bridges = out.bridges + 1;
				x = std::move(t.y), out = std::move(t.r), ties = std::move(t.ties), kept = true;
				distances();
				break;
			}
		}
	}
	for (const auto& f : held) (f.dof() < 2 ? out.duplicateWalls : out.duplicates)++;
	for (const auto& set : sets)
		for (const auto& f : set) (f.dof() < 2 ? out.duplicateWallsApart : out.duplicatesApart)++;
	out.duplicatesApart -= out.duplicates, out.duplicateWallsApart -= out.duplicateWalls;
	out.strayMax = OdometryBridge::worst(m.front());
	pb.same = std::move(held), pb.contacts = startTies;
	out.costBefore = pb.cost(start);  // with the first round's ties and the pairs kept
	return finish(std::move(x));
}
}  // namespace whiskermap::smooth
