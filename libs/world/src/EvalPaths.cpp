#include <whiskermap/core/Angles.h>
#include <whiskermap/world/EvalPaths.h>
#include <whiskermap/world/Trajectory.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>

namespace whiskermap::world
{
namespace
{
using Pose = mrpt::poses::CPose2D;
using Label = std::pair<int, int>;  // (table, leg); table -1 for a wall

/** Fisher-Yates with the project's generator (std::shuffle is not the same everywhere). */
template <class T>
void shuffle(std::vector<T>& v, mrpt::random::CRandomGenerator& rng)
{
	for (size_t i = v.size(); i > 1; i--) std::swap(v[i - 1], v[rng.drawUniform32bit() % i]);
}

/** Noiseless simulator used only for its geometry (what each whisker touches). */
class Toucher
{
   public:
	Toucher(const World& w, const Robot& r) : m_sim(w, r, {}, 1) {}
	bool free(const Pose& p) const { return m_sim.poseIsFree(p); }
	std::vector<Label> labels(const Pose& p)
	{
		std::vector<Label> out;
		const auto sweep = m_sim.sense(p, mrpt::Clock::fromDouble(0), &m_truth);
		for (size_t i = 0; i < m_truth.size(); i++)
			if (sweep->whiskers[i].touched) out.emplace_back(m_truth[i].table, m_truth[i].leg);
		return out;
	}

   private:
	WhiskerSimulator m_sim;
	std::vector<WhiskerSimulator::Truth> m_truth;
};

/** A pose snapped to 1 mm and 0.1 degree: a path file holds exactly these values. */
Pose snapped(double x, double y, double yaw)
{
	return Pose(
		std::round(x * 1000) / 1000, std::round(y * 1000) / 1000,
		core::deg2rad(std::round(core::rad2deg(yaw) * 10) / 10));
}

struct Visit
{
	Pose pose;
	std::vector<Label> labels;
};

/** A free pose that touches leg `k` of table `t` and nothing else but walls: preferably
 *  with two contacts or more on the leg. */
std::optional<Visit> visitLeg(
	const World& w, Toucher& toucher, int t, int k, mrpt::random::CRandomGenerator& rng)
{
	const auto& table = w.tables[t];
	const Eigen::Vector2d c = table.legCentre(k), out = c - Eigen::Vector2d(table.x, table.y);
	const double outward = std::atan2(out.y(), out.x());
	for (int tries = 0; tries < 600; tries++)
	{
		const double a = outward + core::deg2rad(rng.drawUniform(-70.0, 70.0));
		const double d = rng.drawUniform(0.15, 0.45);
		const Pose p = snapped(c.x() + d * std::cos(a), c.y() + d * std::sin(a), rng.drawUniform(-M_PI, M_PI));
		if (!toucher.free(p)) continue;
		auto labels = toucher.labels(p);
		int onLeg = 0;
		bool other = false;
		for (const auto& l : labels)
		{
			onLeg += l == Label{t, k};
			other = other || (l.first >= 0 && l != Label{t, k});
		}
		if (!other && (onLeg >= 2 || (onLeg == 1 && tries >= 300))) return Visit{p, std::move(labels)};
	}
	return std::nullopt;
}

/** Free poses near the walls that touch walls only (at least once). */
std::vector<Visit> wallFillers(const World& w, Toucher& toucher, mrpt::random::CRandomGenerator& rng)
{
	std::vector<Visit> fillers;
	for (int tries = 0; tries < 4000 && fillers.size() < 12; tries++)
	{
		const int side = int(rng.drawUniform32bit() % 4);
		const double d = rng.drawUniform(0.15, 0.35);
		const double u = rng.drawUniform(0.3, 0.7);  // position along the wall, fraction
		const double x = side < 2 ? (side == 0 ? w.x_min + d : w.x_max - d) : w.x_min + u * (w.x_max - w.x_min);
		const double y = side < 2 ? w.y_min + u * (w.y_max - w.y_min) : (side == 2 ? w.y_min + d : w.y_max - d);
		const Pose p = snapped(x, y, rng.drawUniform(-M_PI, M_PI));
		if (!toucher.free(p)) continue;
		auto labels = toucher.labels(p);
		if (!labels.empty() && std::all_of(labels.begin(), labels.end(), [](const Label& l) { return l.first < 0; }))
			fillers.push_back(Visit{p, std::move(labels)});
	}
	return fillers;
}
}  // namespace

std::vector<Pose> EvalPaths::freeGrid(const World& world, const Robot& robot, int n, size_t* dropped)
{
	const WhiskerSimulator sim(world, robot, {}, 1);
	std::vector<Pose> poses;
	size_t blocked = 0;
	for (const auto& p : Trajectory::paperGrid(world, n))
	{
		const Pose q = snapped(p.x(), p.y(), p.phi());
		if (sim.poseIsFree(q))
			poses.push_back(q);
		else
			blocked++;
	}
	if (dropped) *dropped = blocked;
	return poses;
}

bool EvalPaths::gridConnected(const World& world, const Robot& robot, int n)
{
	const WhiskerSimulator sim(world, robot, {}, 1);
	const double dx = (world.x_max - world.x_min) / n, dy = (world.y_max - world.y_min) / n;
	auto at = [&](int i) { return Eigen::Vector2d(world.x_min + (i % n + 0.5) * dx, world.y_min + (i / n + 0.5) * dy); };
	auto freeAt = [&](const Eigen::Vector2d& p) { return sim.poseIsFree(Pose(p.x(), p.y(), 0)); };
	auto freeMove = [&](int a, int b) {
		const int steps = int(std::ceil(std::max(dx, dy) / 0.01));
		for (int s = 1; s < steps; s++)
			if (!freeAt(at(a) + (at(b) - at(a)) * double(s) / steps)) return false;
		return true;
	};
	std::vector<int> state(n * n, 0);  // 0 blocked, 1 free, 2 reached
	int freeCount = 0, start = -1;
	for (int i = 0; i < n * n; i++)
		if (freeAt(at(i))) state[i] = 1, freeCount++, start = start < 0 ? i : start;
	if (start < 0) return false;
	std::queue<int> open;
	open.push(start);
	state[start] = 2;
	int reached = 1;
	while (!open.empty())
	{
		const int a = open.front();
		open.pop();
		const int col = a % n, row = a / n;
		for (const auto& [c, r] : {std::pair{col + 1, row}, {col - 1, row}, {col, row + 1}, {col, row - 1}})
		{
			if (c < 0 || r < 0 || c >= n || r >= n) continue;
			const int b = r * n + c;
			if (state[b] != 1 || !freeMove(a, b)) continue;
			state[b] = 2, reached++;
			open.push(b);
		}
	}
	return reached == freeCount;
}

std::optional<std::vector<Pose>> EvalPaths::sparse(
	const World& world, const Robot& robot, size_t window, int legsPerTable, int visitsPerLeg,
	mrpt::random::CRandomGenerator& rng)
{
	Toucher toucher(world, robot);
	const auto fillers = wallFillers(world, toucher, rng);
	if (fillers.empty()) return std::nullopt;

	// visits[t][slot][v]: the poses touching the slot-th chosen leg of table t.
	const int T = int(world.tables.size());
	std::vector<std::vector<std::vector<Visit>>> visits(T);
	for (int t = 0; t < T; t++)
	{
		std::vector<int> legs{0, 1, 2, 3};
		shuffle(legs, rng);
		for (int k : legs)
		{
			if (int(visits[t].size()) == legsPerTable) break;
			std::vector<Visit> ofLeg;
			for (int v = 0; v < visitsPerLeg; v++)
				if (auto vis = visitLeg(world, toucher, t, k, rng)) ofLeg.push_back(std::move(*vis));
			if (int(ofLeg.size()) == visitsPerLeg) visits[t].push_back(std::move(ofLeg));
		}
		if (visits[t].size() < 2) return std::nullopt;
	}

	// Interleave: round v, leg slot s, tables in a fresh random order each time; a wall-only
	// pose goes in front of a visit while the last window - 1 contacts hold another leg of
	// its table.
	std::vector<Pose> path;
	std::vector<Label> stream;
	size_t nextFiller = 0;
	auto append = [&](const Visit& v) {
		path.push_back(v.pose);
		stream.insert(stream.end(), v.labels.begin(), v.labels.end());
	};
	std::vector<int> order(T);
	std::iota(order.begin(), order.end(), 0);
	for (int v = 0; v < visitsPerLeg; v++)
		for (int s = 0; s < legsPerTable; s++)
		{
			shuffle(order, rng);
			for (int t : order)
			{
				if (s >= int(visits[t].size())) continue;
				const Visit& vis = visits[t][s][v];
				const int leg = std::find_if(vis.labels.begin(), vis.labels.end(), [&](const Label& l) {
									return l.first == t;
								})->second;
				auto clash = [&] {
					const size_t from = stream.size() > window - 1 ? stream.size() - (window - 1) : 0;
					for (size_t i = from; i < stream.size(); i++)
						if (stream[i].first == t && stream[i].second != leg) return true;
					return false;
				};
				while (clash()) append(fillers[nextFiller++ % fillers.size()]);
				append(vis);
			}
		}
	return path;
}
}  // namespace whiskermap::world
