#include <whiskermap/baseline/LeastSquares.h>
#include <whiskermap/baseline/TableMatcher.h>
#include <whiskermap/core/Angles.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

namespace whiskermap::baseline
{
TableMatcher::TableMatcher(
	const std::vector<Contact>& contacts, const std::vector<LegFit>& legs, const FreeSpace& free,
	const TBaselineParams& p)
	: m_contacts(contacts), m_legs(legs), m_free(free), m_p(p), m_cell(std::hypot(p.table_length, p.table_width) + 0.2)
{
	for (size_t j = 0; j < legs.size(); j++)
	{
		// Largest std-dev of the leg centre, with the position floor.
		const double var = legs[j].centreCovariance.selfadjointView<Eigen::Upper>().eigenvalues().maxCoeff();
		m_sigma.push_back(std::sqrt(std::max(0.0, var) + p.position_floor * p.position_floor));
		m_grid[cell(legs[j].centre)].push_back(int(j));
	}
}

TableMatcher::Cell TableMatcher::cell(const Eigen::Vector2d& c) const
{
	return {long(std::floor(c.x() / m_cell)), long(std::floor(c.y() / m_cell))};
}

std::vector<int> TableMatcher::legsNear(const Eigen::Vector2d& c) const
{
	std::vector<int> out;
	const auto [cx, cy] = cell(c);
	for (long dx = -1; dx <= 1; dx++)
		for (long dy = -1; dy <= 1; dy++)
			if (const auto it = m_grid.find({cx + dx, cy + dy}); it != m_grid.end())
				out.insert(out.end(), it->second.begin(), it->second.end());
	std::sort(out.begin(), out.end());
	return out;
}

bool TableMatcher::legFits(const TableEstimate& t, int corner, int leg, double slack) const
{
	const auto& l = m_legs[leg];
	const double yawTol = m_p.angle_tolerance + 3 * l.yawSigma;
	return (l.centre - t.corner(corner, m_p)).norm() <= m_p.spacing_tolerance + 3 * m_sigma[leg] + slack &&
		   std::abs(core::angleDiff(t.yaw, l.yaw, M_PI / 2)) <= yawTol;
}

void TableMatcher::collect(TableEstimate& t, const std::vector<bool>& taken, double slack) const
{
	const auto near = legsNear(t.centre);  // every corner is within a cell of the centre
	for (int k = 0; k < 4; k++)
	{
		if (t.legs[k] >= 0) continue;
		double best = INFINITY;
		for (int j : near)
		{
			if (taken[j] || std::find(t.legs.begin(), t.legs.end(), j) != t.legs.end()) continue;
			const double d = (m_legs[j].centre - t.corner(k, m_p)).norm();
			if (d < best && legFits(t, k, j, slack)) best = d, t.legs[k] = j;
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

std::vector<TableMatcher::Seed> TableMatcher::seeds() const
{
	// Leg pairs no further apart than the diagonal (+ 20 cm): the grid's cell size.
	std::vector<Seed> out;
	for (int a = 0; a < int(m_legs.size()); a++)
	{
		std::vector<int> near;
		for (int b : legsNear(m_legs[a].centre))
			if (b > a && (m_legs[b].centre - m_legs[a].centre).norm() <= m_cell) near.push_back(b);
		for (int b : near)
		{
			const Eigen::Vector2d v = m_legs[b].centre - m_legs[a].centre;
			const double D = v.norm();
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
					if (std::abs(D - o.norm()) <= m_p.spacing_tolerance + 3 * sigmaD) out.push_back({a, b, ka, kb});
				}
		}
	}
	return out;
}

std::optional<TableEstimate> TableMatcher::propose(const Seed& s, const std::vector<bool>& taken, std::vector<int>& used) const
{
	const auto& la = m_legs[s.a];
	const auto& lb = m_legs[s.b];
	const Eigen::Vector2d v = lb.centre - la.centre;
	const Eigen::Vector2d o = TableEstimate::offset(s.kb, m_p) - TableEstimate::offset(s.ka, m_p);
	TableEstimate t;
	t.yaw = core::wrapToPi(std::atan2(v.y(), v.x()) - std::atan2(o.y(), o.x()));
	t.legs[s.ka] = s.a, t.legs[s.kb] = s.b;
	t.centre = (la.centre + lb.centre) / 2 -
			   Eigen::Rotation2Dd(t.yaw) * (TableEstimate::offset(s.ka, m_p) + TableEstimate::offset(s.kb, m_p)) / 2;
	used.clear();
	if (!legFits(t, s.ka, s.a, INFINITY) || !legFits(t, s.kb, s.b, INFINITY)) return std::nullopt;
	m_proposals++;
	auto remember = [&] {
		for (int l : t.legs)
			if (l >= 0 && std::find(used.begin(), used.end(), l) == used.end()) used.push_back(l);
	};
	// A two-leg pose is rough: collect with slack, fit, then keep what still fits.
	collect(t, taken, 3 * (m_sigma[s.a] + m_sigma[s.b]));
	remember();
	fitToLegs(t);
	for (int k = 0; k < 4; k++)
		if (t.legs[k] >= 0 && !legFits(t, k, t.legs[k], 0)) t.legs[k] = -1;
	if (t.legCount() < 2) return std::nullopt;
	collect(t, taken, 0);
	remember();
	fitToLegs(t);
	if (contradictedByFreeSpace(t))
	{
		m_contradicted++;
		return std::nullopt;
	}
	return t;
}

std::vector<TableEstimate> TableMatcher::run()
{
	std::vector<bool> taken(m_legs.size(), false);
	std::vector<TableEstimate> tables;
	const auto all = seeds();
	// One proposal per seed, with the legs it considered: a proposal is rebuilt only when a
	// leg it considered is taken, and dropped when it overlaps an accepted table.
	std::vector<std::optional<TableEstimate>> proposals(all.size());
	std::vector<std::vector<int>> used(all.size());
	for (size_t i = 0; i < all.size(); i++) proposals[i] = propose(all[i], taken, used[i]);
	auto better = [](const TableEstimate& x, const TableEstimate& y) {
		if (x.legCount() != y.legCount()) return x.legCount() > y.legCount();
		return x.cost < y.cost;
	};
	for (;;)
	{
		size_t best = SIZE_MAX;
		for (size_t i = 0; i < all.size(); i++)
			if (proposals[i] && (best == SIZE_MAX || better(*proposals[i], *proposals[best]))) best = i;
		if (best == SIZE_MAX) break;
		TableEstimate t = *proposals[best];
		t.fitToContacts(m_legs, m_contacts, m_p);
		// The precise pose may reach one more leg.
		collect(t, taken, 0);
		t.fitToContacts(m_legs, m_contacts, m_p);
		for (int l : t.legs)
			if (l >= 0) taken[l] = true;
		tables.push_back(t);
		for (size_t i = 0; i < all.size(); i++)
		{
			if (!proposals[i] && used[i].empty()) continue;  // never viable
			bool rebuilt = false;
			if (taken[all[i].a] || taken[all[i].b])
				proposals[i].reset(), used[i].clear();
			else if (std::any_of(used[i].begin(), used[i].end(), [&](int l) { return taken[l]; }))
				proposals[i] = propose(all[i], taken, used[i]), rebuilt = true;
			// A kept proposal was checked against the earlier tables already.
			if (proposals[i] && (rebuilt ? std::any_of(tables.begin(), tables.end(), [&](const TableEstimate& a) {
									return a.overlaps(*proposals[i], m_p);
								})
										 : t.overlaps(*proposals[i], m_p)))
				proposals[i].reset();
		}
	}
	return tables;
}
}  // namespace whiskermap::baseline
