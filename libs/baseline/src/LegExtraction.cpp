#include <whiskermap/baseline/FaceResidual.h>
#include <whiskermap/baseline/LegExtraction.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>

namespace whiskermap::baseline
{
namespace
{
/** Union-find over contact indices. */
struct Components
{
	std::vector<size_t> parent;
	explicit Components(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
	size_t root(size_t i)
	{
		while (parent[i] != i) i = parent[i] = parent[parent[i]];
		return i;
	}
	void join(size_t a, size_t b) { parent[root(a)] = root(b); }
};

/** Single-linkage clusters of `points` (pairs within `radius(i, j)` <= maxRadius). */
std::vector<std::vector<size_t>> singleLinkage(
	const std::vector<Eigen::Vector2d>& points, const std::vector<size_t>& ids, double maxRadius,
	const std::function<double(size_t, size_t)>& radius)
{
	std::map<std::pair<long, long>, std::vector<size_t>> grid;
	auto cell = [&](const Eigen::Vector2d& q) {
		return std::pair<long, long>(long(std::floor(q.x() / maxRadius)), long(std::floor(q.y() / maxRadius)));
	};
	for (size_t j = 0; j < ids.size(); j++) grid[cell(points[j])].push_back(j);
	Components comp(ids.size());
	for (size_t j = 0; j < ids.size(); j++)
	{
		const auto [cx, cy] = cell(points[j]);
		for (long dx = -1; dx <= 1; dx++)
			for (long dy = -1; dy <= 1; dy++)
			{
				const auto it = grid.find({cx + dx, cy + dy});
				if (it == grid.end()) continue;
				for (size_t k : it->second)
					if (k > j && (points[j] - points[k]).norm() <= radius(ids[j], ids[k])) comp.join(j, k);
			}
	}
	std::map<size_t, std::vector<size_t>> byRoot;
	for (size_t j = 0; j < ids.size(); j++) byRoot[comp.root(j)].push_back(ids[j]);
	std::vector<std::vector<size_t>> clusters;
	for (auto& [root, members] : byRoot) clusters.push_back(std::move(members));
	return clusters;
}

class Extractor
{
   public:
	Extractor(const std::vector<Contact>& c, const TBaselineParams& p, LegExtraction& out) : m_c(c), m_p(p), m_out(out) {}

	/** Accepts `members` as a leg, or splits it, or rejects it. */
	void accept(const std::vector<size_t>& members, int depth)
	{
		auto leg = LegFit::fit(m_c, members, m_p);
		if (leg.legShaped(m_p))
		{
			if (textureMatches(leg))
				m_out.legs.push_back(std::move(leg));
			else
				reject(members);
			return;
		}
		if (depth < 3 && members.size() >= 2)
		{
			const auto [a, b] = twoLegs(members);
			if (a.legShaped(m_p) && b.legShaped(m_p) && (separated(a.members, b.members) || (a.faces >= 2 && b.faces >= 2)))
			{
				m_out.splits++;
				accept(a.members, depth + 1);
				accept(b.members, depth + 1);
				return;
			}
		}
		reject(members);
	}

   private:
	/** The members' textures are texture_evidence nats more likely under the table's
	 *  texture (Gaussian, the sweep's sigma_tau with the floor) than under any texture
	 *  (uniform on [0, 1], log-density 0). */
	bool textureMatches(const LegFit& leg) const
	{
		double evidence = 0;
		for (size_t i : leg.members)
		{
			const double s = std::hypot(m_c[i].sigma_tau, m_p.texture_floor), z = (m_c[i].texture - m_p.texture) / s;
			evidence += -0.5 * z * z - std::log(s * std::sqrt(2 * M_PI));
		}
		return evidence >= m_p.texture_evidence;
	}

	void reject(const std::vector<size_t>& members)
	{
		m_out.clustersRejected++;
		m_out.contactsRejected += members.size();
	}

	Eigen::Vector2d pointed(size_t i) const { return LegFit::pointedCentre(m_c[i], m_p.leg_width); }

	/** Two groups by 2-means on the pointed centres, started from the two farthest apart. */
	std::pair<std::vector<size_t>, std::vector<size_t>> twoMeans(const std::vector<size_t>& members) const
	{
		Eigen::Vector2d ca = pointed(members[0]), cb = ca;
		double far = -1;
		for (size_t i : members)
			for (size_t j : members)
				if ((pointed(i) - pointed(j)).squaredNorm() > far)
					far = (pointed(i) - pointed(j)).squaredNorm(), ca = pointed(i), cb = pointed(j);
		std::vector<size_t> a, b;
		for (int it = 0; it < 20; it++)
		{
			a.clear(), b.clear();
			for (size_t i : members) ((pointed(i) - ca).squaredNorm() <= (pointed(i) - cb).squaredNorm() ? a : b).push_back(i);
			Eigen::Vector2d na(0, 0), nb(0, 0);
			for (size_t i : a) na += pointed(i) / double(a.size());
			for (size_t i : b) nb += pointed(i) / double(b.size());
			if (na == ca && nb == cb) break;
			ca = na, cb = nb;
		}
		return {a, b};
	}

	/** Two legs for one cluster: 2-means on the pointed centres, then each contact moved to
	 *  the leg whose faces fit it better and both legs refitted, a few times. */
	std::pair<LegFit, LegFit> twoLegs(const std::vector<size_t>& members) const
	{
		auto [ia, ib] = twoMeans(members);
		if (ia.empty() || ib.empty()) return {LegFit::fit(m_c, members, m_p), LegFit{}};
		LegFit a = LegFit::fit(m_c, ia, m_p), b = LegFit::fit(m_c, ib, m_p);
		for (int it = 0; it < 4; it++)
		{
			std::vector<size_t> na, nb;
			for (size_t i : members)
			{
				const auto ra = FaceResidual::best(m_c[i], a.centre, a.yaw, m_p), rb = FaceResidual::best(m_c[i], b.centre, b.yaw, m_p);
				(ra.cost() <= rb.cost() ? na : nb).push_back(i);
			}
			if (na.empty() || nb.empty() || (na == a.members && nb == b.members)) break;
			a = LegFit::fit(m_c, na, m_p), b = LegFit::fit(m_c, nb, m_p);
		}
		return {a, b};
	}

	/** The two groups are apart: their closest pointed centres are further apart than the
	 *  spacing of neighbours inside either group (a flat surface, evenly touched, is not). */
	bool separated(const std::vector<size_t>& a, const std::vector<size_t>& b) const
	{
		if (a.empty() || b.empty()) return false;
		double between = INFINITY;
		for (size_t i : a)
			for (size_t j : b) between = std::min(between, (pointed(i) - pointed(j)).norm());
		auto innerGap = [&](const std::vector<size_t>& g) {
			double worst = 0;  // largest nearest-neighbour distance inside the group
			for (size_t i : g)
			{
				double nearest = INFINITY;
				for (size_t j : g)
					if (j != i) nearest = std::min(nearest, (pointed(i) - pointed(j)).norm());
				if (g.size() > 1) worst = std::max(worst, nearest);
			}
			return worst;
		};
		return between > std::max({innerGap(a), innerGap(b), m_p.leg_width / 5});
	}

	const std::vector<Contact>& m_c;
	const TBaselineParams& m_p;
	LegExtraction& m_out;
};
}  // namespace

LegExtraction LegExtraction::run(const std::vector<Contact>& contacts, const TBaselineParams& p)
{
	LegExtraction out;
	std::vector<size_t> ids;
	std::vector<Eigen::Vector2d> points;
	double maxSigmaR = 0;
	for (size_t i = 0; i < contacts.size(); i++)
	{
		const auto& c = contacts[i];
		if (std::abs(c.texture - p.texture) > p.texture_gate * std::hypot(c.sigma_tau, p.texture_floor))
		{
			out.textureRejected++;
			continue;
		}
		ids.push_back(i);
		points.push_back(LegFit::pointedCentre(c, p.leg_width));
		maxSigmaR = std::max(maxSigmaR, c.sigma_r);
	}
	out.contactsUsed = ids.size();
	const double base = p.link_distance * p.leg_width;
	const auto radius = [&](size_t i, size_t j) {
		return base + 2 * std::max(contacts[i].sigma_r, contacts[j].sigma_r);
	};
	Extractor ex(contacts, p, out);
	for (const auto& cluster : singleLinkage(points, ids, base + 2 * maxSigmaR, radius)) ex.accept(cluster, 0);
	return out;
}
}  // namespace whiskermap::baseline
