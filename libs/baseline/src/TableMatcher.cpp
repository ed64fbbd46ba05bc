#include <whiskermap/baseline/LeastSquares.h>
#include <whiskermap/baseline/TableMatcher.h>
#include <whiskermap/core/Angles.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace whiskermap::baseline
{
TableMatcher::TableMatcher(
	const std::vector<Contact>& contacts, const std::vector<LegFit>& legs, const FreeSpace& free,
	const TBaselineParams& p)
	: m_contacts(contacts), m_legs(legs), m_free(free), m_p(p)
{
}

double TableMatcher::legSigma(int leg) const
{
	// Largest std-dev of the leg centre, with the position floor.
	const double var = m_legs[leg].centreCovariance.selfadjointView<Eigen::Upper>().eigenvalues().maxCoeff();
	return std::sqrt(std::max(0.0, var) + m_p.position_floor * m_p.position_floor);
}

bool TableMatcher::legFits(const TableEstimate& t, int corner, int leg, double slack) const
{
	const auto& l = m_legs[leg];
	const double yawTol = m_p.angle_tolerance + 3 * l.yawSigma;
	return (l.centre - t.corner(corner, m_p)).norm() <= m_p.spacing_tolerance + 3 * legSigma(leg) + slack &&
		   std::abs(core::angleDiff(t.yaw, l.yaw, M_PI / 2)) <= yawTol;
}

void TableMatcher::collect(TableEstimate& t, const std::vector<bool>& taken, double slack) const
{
	for (int k = 0; k < 4; k++)
	{
		if (t.legs[k] >= 0) continue;
		double best = INFINITY;
		for (size_t j = 0; j < m_legs.size(); j++)
		{
			if (taken[j] || std::find(t.legs.begin(), t.legs.end(), int(j)) != t.legs.end()) continue;
			const double d = (m_legs[j].centre - t.corner(k, m_p)).norm();
			if (d < best && legFits(t, k, int(j), slack)) best = d, t.legs[k] = int(j);
		}
	}
}

void TableMatcher::fitToLegs(TableEstimate& t) const
{
	const auto residuals = [&](const Eigen::Vector3d& v, std::vector<double>& out) {
		out.clear();
		for (int k = 0; k < 4; k++)
		{
			if (t.legs[k] < 0) continue;
			const auto& l = m_legs[t.legs[k]];
			const Eigen::Vector2d predicted = v.head<2>() + Eigen::Rotation2Dd(v[2]) * TableEstimate::offset(k, m_p);
			const Eigen::Matrix2d cov =
				l.centreCovariance + m_p.position_floor * m_p.position_floor * Eigen::Matrix2d::Identity();
			const Eigen::Vector2d z = cov.llt().matrixL().solve(l.centre - predicted);  // whitened
			out.push_back(z.x());
			out.push_back(z.y());
			out.push_back(core::angleDiff(v[2], l.yaw, M_PI / 2) / std::hypot(l.yawSigma, m_p.angle_floor));
		}
	};
	const auto res = LeastSquares::solve(Eigen::Vector3d(t.centre.x(), t.centre.y(), t.yaw), residuals);
	t.centre = res.x.head<2>(), t.yaw = res.x[2], t.cost = res.cost;
}

bool TableMatcher::contradictedByFreeSpace(const TableEstimate& t) const
{
	const double halfDiagonal = m_p.leg_width / std::sqrt(2.0);
	for (int k = 0; k < 4; k++)
		if (t.legs[k] < 0 && m_free.depth(t.corner(k, m_p)) > halfDiagonal + m_p.free_margin) return true;
	return false;
}

std::vector<TableEstimate> TableMatcher::propose(const std::vector<bool>& taken) const
{
	std::vector<TableEstimate> out;
	const double longest = std::hypot(m_p.table_length, m_p.table_width);
	for (size_t a = 0; a < m_legs.size(); a++)
		for (size_t b = a + 1; b < m_legs.size(); b++)
		{
			if (taken[a] || taken[b]) continue;
			const Eigen::Vector2d v = m_legs[b].centre - m_legs[a].centre;
			const double D = v.norm();
			if (D > longest + 0.2) continue;
			const Eigen::Vector2d u = v / std::max(D, 1e-9);
			const double sigmaD = std::sqrt(
				u.dot(m_legs[a].centreCovariance * u) + u.dot(m_legs[b].centreCovariance * u) +
				2 * m_p.position_floor * m_p.position_floor);
			// Leg a at corner ka, b at kb. A table turned half a turn is the same table with
			// corners k and k + 2 swapped, so ka in {0, 1} covers every case once: two mirror
			// tables per side pair, two per diagonal pair.
			for (int ka = 0; ka < 2; ka++)
				for (int kb = 0; kb < 4; kb++)
				{
					if (ka == kb) continue;
					const Eigen::Vector2d o = TableEstimate::offset(kb, m_p) - TableEstimate::offset(ka, m_p);
					if (std::abs(D - o.norm()) > m_p.spacing_tolerance + 3 * sigmaD) continue;
					TableEstimate t;
					t.yaw = core::wrapToPi(std::atan2(v.y(), v.x()) - std::atan2(o.y(), o.x()));
					t.legs[ka] = int(a), t.legs[kb] = int(b);
					const Eigen::Rotation2Dd R(t.yaw);
					t.centre = (m_legs[a].centre + m_legs[b].centre) / 2 -
							   R * (TableEstimate::offset(ka, m_p) + TableEstimate::offset(kb, m_p)) / 2;
					if (!legFits(t, ka, int(a), INFINITY) || !legFits(t, kb, int(b), INFINITY)) continue;
					m_proposals++;
					// A two-leg pose is rough: collect with slack, fit, then keep what still fits.
					collect(t, taken, 3 * (legSigma(int(a)) + legSigma(int(b))));
					fitToLegs(t);
					for (int k = 0; k < 4; k++)
						if (t.legs[k] >= 0 && !legFits(t, k, t.legs[k], 0)) t.legs[k] = -1;
					if (t.legCount() < 2) continue;
					collect(t, taken, 0);
					fitToLegs(t);
					if (contradictedByFreeSpace(t))
					{
						m_contradicted++;
						continue;
					}
					out.push_back(t);
				}
		}
	return out;
}

std::vector<TableEstimate> TableMatcher::run()
{
	std::vector<bool> taken(m_legs.size(), false);
	std::vector<TableEstimate> tables;
	auto better = [](const TableEstimate& x, const TableEstimate& y) {
		if (x.legCount() != y.legCount()) return x.legCount() > y.legCount();
		return x.cost < y.cost;
	};
	for (;;)
	{
		auto proposals = propose(taken);
		proposals.erase(
			std::remove_if(
				proposals.begin(), proposals.end(),
				[&](const TableEstimate& t) {
					return std::any_of(tables.begin(), tables.end(), [&](const TableEstimate& a) { return a.overlaps(t, m_p); });
				}),
			proposals.end());
		if (proposals.empty()) break;
		TableEstimate best = *std::min_element(proposals.begin(), proposals.end(), better);
		best.fitToContacts(m_legs, m_contacts, m_p);
		// The precise pose may reach one more leg.
		collect(best, taken, 0);
		best.fitToContacts(m_legs, m_contacts, m_p);
		for (int l : best.legs)
			if (l >= 0) taken[l] = true;
		tables.push_back(best);
	}
	return tables;
}
}  // namespace whiskermap::baseline
