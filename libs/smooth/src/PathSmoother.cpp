#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/smooth/ContactFactor.h>
#include <whiskermap/smooth/OdometryFactor.h>
#include <whiskermap/smooth/PathSmoother.h>
#include <whiskermap/smooth/WallLines.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>

namespace whiskermap::smooth
{
namespace
{
/** The problem of one round: the factors, and the variables' layout (poses 1..N-1, then the
 *  group shifts; pose 0 is fixed). */
struct Problem
{
	const std::vector<OdometryFactor>& odometry;
	std::vector<ContactFactor> contacts;
	size_t poses, groups;
	double huber, solidSigma;

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

	double cost(const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector2d>& d) const
	{
		double c = 0;
		for (size_t i = 1; i < poses; i++) c += odometry[i].residual(x[i - 1], x[i]).squaredNorm();  // eq. S2
		for (const auto& f : contacts) c += loss(f.residual(x[f.pose], d[f.group]));  // eq. S3
		for (const auto& s : d) c += s.squaredNorm() / (solidSigma * solidSigma);
		return c;
	}

	/** J^T W J and J^T W r at (x, d). */
	void normalEquations(
		const std::vector<Eigen::Vector3d>& x, const std::vector<Eigen::Vector2d>& d, Eigen::SparseMatrix<double>& H,
		Eigen::VectorXd& b) const
	{
		std::vector<Eigen::Triplet<double>> t;
		t.reserve(18 * poses + 25 * contacts.size() + 2 * groups);
		b = Eigen::VectorXd::Zero(static_cast<long>(size()));
		// Adds the blocks of one residual row set: columns cols[k] (-1: fixed), Jacobian blocks J[k].
		auto add = [&](const Eigen::VectorXd& r, const std::vector<std::pair<long, Eigen::MatrixXd>>& blocks, double w) {
			for (const auto& [ci, Ji] : blocks)
			{
				if (ci < 0) continue;
				b.segment(ci, Ji.cols()) += w * Ji.transpose() * r;
				for (const auto& [cj, Jj] : blocks)
				{
					if (cj < 0) continue;
					const Eigen::MatrixXd h = w * Ji.transpose() * Jj;
					for (long u = 0; u < h.rows(); u++)
						for (long v = 0; v < h.cols(); v++) t.emplace_back(ci + u, cj + v, h(u, v));
				}
			}
		};
		for (size_t i = 1; i < poses; i++)
		{
			Eigen::Matrix3d Ja, Jb;
			const Eigen::Vector3d r = odometry[i].residual(x[i - 1], x[i], &Ja, &Jb);
			add(r, {{poseColumn(i - 1), Ja}, {poseColumn(i), Jb}}, 1);
		}
		for (const auto& f : contacts)
		{
			Eigen::Vector3d Jx;
			Eigen::Vector2d Jd;
			const double r = f.residual(x[f.pose], d[f.group], &Jx, &Jd);
			double w;
			loss(r, &w);
			add(Eigen::VectorXd::Constant(1, r), {{poseColumn(f.pose), Jx.transpose()}, {groupColumn(f.group), Jd.transpose()}}, w);
		}
		for (size_t g = 0; g < groups; g++)
			add(d[g] / solidSigma, {{groupColumn(g), Eigen::Matrix2d::Identity() / solidSigma}}, 1);
		H.resize(static_cast<long>(size()), static_cast<long>(size()));
		H.setFromTriplets(t.begin(), t.end());
	}
};
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
	out.path = in.path;
	out.shifts.assign(groups, Eigen::Vector2d::Zero());
	Problem pb{odometry, {}, n, groups, params.huber, params.solid_sigma};
	if (n == 1) return out;

	for (unsigned round = 0; round < params.rounds; round++)
	{
		pb.contacts.clear();
		for (const auto& c : in.contacts)
			if (auto f = ContactFactor::associate(
					c, c.sweep, out.path[c.sweep], solids, out.groupOf, out.shifts, params.gate, params.normal_gate,
					params.position_floor))
				pb.contacts.push_back(*f);
		out.tied = pb.contacts.size();
		double cost = pb.cost(out.path, out.shifts);
		if (round == 0) out.costBefore = cost;
		out.rounds = round + 1;
		double lambda = 1e-4, firstCost = cost;
		for (unsigned it = 0; it < params.iterations; it++)
		{
			Eigen::SparseMatrix<double> H;
			Eigen::VectorXd b;
			pb.normalEquations(out.path, out.shifts, H, b);
			bool stepped = false;
			for (int tries = 0; tries < 8 && !stepped; tries++)
			{
				Eigen::SparseMatrix<double> A = H;
				for (long k = 0; k < A.rows(); k++) A.coeffRef(k, k) += lambda * (H.coeff(k, k) + 1e-9);
				Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
				if (solver.info() != Eigen::Success) { lambda *= 10; continue; }
				const Eigen::VectorXd dx = solver.solve(-b);
				auto path = out.path;
				auto shifts = out.shifts;
				for (size_t i = 1; i < n; i++)
				{
					path[i] += dx.segment<3>(pb.poseColumn(i));
					path[i][2] = core::wrapToPi(path[i][2]);
				}
				for (size_t g = 0; g < groups; g++) shifts[g] += dx.segment<2>(pb.groupColumn(g));
				const double c = pb.cost(path, shifts);
				if (c < cost)
				{
					out.path = std::move(path), out.shifts = std::move(shifts);
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
	return out;
}
}  // namespace whiskermap::smooth
