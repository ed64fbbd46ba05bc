#include <mrpt/random/RandomGenerators.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/core/SeedStream.h>
#include <whiskermap/world/PathPlanner.h>
#include <whiskermap/world/TrajectoryGenerator.h>
#include <whiskermap/world/WhiskerSimulator.h>

#include <cmath>

namespace whiskermap::world
{
namespace
{
using Vec = Eigen::Vector2d;
constexpr uint64_t TRAJECTORY_STREAM = 2;
constexpr double EXPLORE_DEFAULT_DURATION = 120;
constexpr double PLACE_GAP = 0.25;  // metres between the places a lawnmower or wall-follow visits

/** Turns polylines into poses: steps of at most `step` metres and `maxTurn` radians, a pose at
 *  every vertex, in-place turns where a corner is sharper than one step's turn; stops adding
 *  poses once the sweep count or the length limit is reached. */
class Driver
{
   public:
	Driver(double step, double maxTurn, size_t maxPoses, double maxLength)
		: m_step(step), m_maxTurn(maxTurn), m_maxPoses(maxPoses), m_maxLength(maxLength)
	{
	}
	void start(const Vec& p, double heading) { m_poses.emplace_back(p.x(), p.y(), heading); }
	bool full() const
	{
		return (m_maxPoses && m_poses.size() >= m_maxPoses) || (m_maxLength > 0 && m_travelled >= m_maxLength);
	}
	Vec position() const { return {m_poses.back().x(), m_poses.back().y()}; }
	double travelled() const { return m_travelled; }
	std::vector<mrpt::poses::CPose2D>& poses() { return m_poses; }

	/** Turns in place so that at most one step's turn remains towards `heading` (`all`: none). */
	void turnTowards(double heading, bool all = false)
	{
		const double theta = m_poses.back().phi(), d = core::wrapToPi(heading - theta);
		const int steps = int(std::ceil(std::abs(d) / m_maxTurn - 1e-9));
		const int inPlace = all ? steps : steps - 1;
		const Vec p = position();
		for (int k = 1; k <= inPlace && !full(); k++) emit(p, theta + d * k / std::max(steps, 1));
	}
	void lineTo(const Vec& q)
	{
		const Vec p = position();
		const double len = (q - p).norm();
		if (len < 1e-9) return;
		const double heading = std::atan2(q.y() - p.y(), q.x() - p.x());
		turnTowards(heading);
		const int n = int(std::ceil(len / m_step - 1e-9));
		for (int k = 1; k <= n && !full(); k++)
		{
			m_travelled += len / n;
			emit(k == n ? q : Vec(p + (q - p) * (double(k) / n)), heading);  // exactly q at the end
		}
	}

   private:
	void emit(const Vec& p, double heading) { m_poses.emplace_back(p.x(), p.y(), core::wrapToPi(heading)); }

	double m_step, m_maxTurn;
	size_t m_maxPoses;
	double m_maxLength, m_travelled = 0;
	std::vector<mrpt::poses::CPose2D> m_poses;
};

/** Drives the free way to `goal` (made reachable first). */
void driveTo(Driver& d, const PathPlanner& planner, const Vec& goal)
{
	const auto way = planner.route(d.position(), planner.reachable(goal));
	for (size_t i = 1; i < way.size() && !d.full(); i++) d.lineTo(way[i]);
}

/** Drives along the straight line to `goal` through places PLACE_GAP apart, leaving out the
 *  places the body cannot reach, so that detours round legs stay short and local. */
void driveAlong(Driver& d, const PathPlanner& planner, const Vec& goal)
{
	const Vec from = d.position();
	const int n = std::max(1, int(std::ceil((goal - from).norm() / PLACE_GAP - 1e-9)));
	for (int k = 1; k < n && !d.full(); k++)
		if (const Vec p = from + (goal - from) * (double(k) / n); planner.inRegion(p)) driveTo(d, planner, p);
	if (!d.full()) driveTo(d, planner, goal);
}

std::vector<Vec> lawnmowerRows(const World& w, const TrajectorySpec& s)
{
	const double height = w.y_max - w.y_min - 2 * s.standoff;
	const int rows = height < 0 ? 1 : int(std::floor(height / s.spacing + 1e-9)) + 1;
	const double y0 = (w.y_min + w.y_max) / 2 - (rows - 1) * s.spacing / 2;
	const double xl = w.x_min + s.standoff, xr = w.x_max - s.standoff;
	std::vector<Vec> out;
	for (int r = 0; r < rows; r++)
	{
		const double y = y0 + r * s.spacing;
		out.emplace_back(r % 2 ? xr : xl, y);
		out.emplace_back(r % 2 ? xl : xr, y);
	}
	return out;
}

std::vector<Vec> wallCircuit(const World& w, double d)
{
	return {{w.x_min + d, w.y_min + d}, {w.x_max - d, w.y_min + d}, {w.x_max - d, w.y_max - d}, {w.x_min + d, w.y_max - d},
			{w.x_min + d, w.y_min + d}};
}

/** Eight places round the centre at random radii (20-40% of the arena's size), then the first. */
std::vector<Vec> loopTour(const World& w, mrpt::random::CRandomGenerator& rng)
{
	const Vec c((w.x_min + w.x_max) / 2, (w.y_min + w.y_max) / 2);
	const double a0 = rng.drawUniform(0.0, 2 * M_PI);
	std::vector<Vec> out;
	for (int k = 0; k < 8; k++)
	{
		const double a = a0 + 2 * M_PI * k / 8, f = rng.drawUniform(0.2, 0.4);
		out.emplace_back(c.x() + (w.x_max - w.x_min) * f * std::cos(a), c.y() + (w.y_max - w.y_min) * f * std::sin(a));
	}
	out.push_back(out.front());
	return out;
}
}  // namespace

TrajectorySpec::Kind TrajectorySpec::parseKind(const std::string& name)
{
	if (name == "lawnmower") return Kind::Lawnmower;
	if (name == "explore") return Kind::Explore;
	if (name == "wall-follow") return Kind::WallFollow;
	if (name == "loop") return Kind::Loop;
	throw core::Error("unknown trajectory '" + name + "' (lawnmower, explore, wall-follow, loop)");
}

void TrajectorySpec::validate() const
{
	auto check = [](bool ok, const std::string& what) {
		if (!ok) throw core::Error("trajectory: " + what);
	};
	check(speed > 0 && speed <= 10, "speed must be in (0, 10] m/s");
	check(rate > 0 && rate <= 1000, "rate must be in (0, 1000] Hz");
	check(turn_rate_deg > 0 && turn_rate_deg <= 3600, "turn rate must be in (0, 3600] deg/s");
	check(duration >= 0 && duration <= 1e6, "duration must be in [0, 1e6] s");
	check(length >= 0 && length <= 1e6, "length must be in [0, 1e6] m");
	check(spacing > 0 && spacing <= 100, "spacing must be in (0, 100] m");
	check(standoff >= 0 && standoff <= 100, "standoff must be in [0, 100] m");
}

std::vector<mrpt::poses::CPose2D> TrajectoryGenerator::generate(
	const World& w, const Robot& robot, const TrajectorySpec& s, uint64_t seed)
{
	s.validate();
	mrpt::random::CRandomGenerator rng(core::seedStream(seed, TRAJECTORY_STREAM));
	const PathPlanner planner(w, robot.radius);
	const double duration = s.kind == TrajectorySpec::Kind::Explore && s.duration == 0 && s.length == 0
								? EXPLORE_DEFAULT_DURATION
								: s.duration;
	const size_t maxPoses = duration > 0 ? size_t(std::floor(duration * s.rate + 1e-9)) + 1 : 0;
	const bool limited = maxPoses > 0 || s.length > 0;
	Driver d(s.speed / s.rate, core::deg2rad(s.turn_rate_deg) / s.rate, maxPoses, s.length);

	std::vector<Vec> pattern;
	if (s.kind == TrajectorySpec::Kind::Lawnmower) pattern = lawnmowerRows(w, s);
	if (s.kind == TrajectorySpec::Kind::WallFollow) pattern = wallCircuit(w, s.standoff);
	if (s.kind == TrajectorySpec::Kind::Loop) pattern = loopTour(w, rng);
	const Vec first = planner.reachable(
		pattern.empty() ? Vec((w.x_min + w.x_max) / 2, (w.y_min + w.y_max) / 2) : pattern.front());
	double heading = 0;  // explore starts facing +x; a pattern along its first way
	if (pattern.size() > 1)
	{
		const auto way = planner.route(first, planner.reachable(pattern[1]));
		heading = std::atan2(way[1].y() - first.y(), way[1].x() - first.x());
	}
	d.start(first, heading);

	for (int pass = 0; !d.full() && (pass == 0 || limited); pass++)
	{
		const size_t before = d.poses().size();
		if (s.kind == TrajectorySpec::Kind::Explore)
		{
			// A random reachable place, preferably a quarter of the arena away or more.
			const double far = 0.25 * std::min(w.x_max - w.x_min, w.y_max - w.y_min);
			Vec goal = d.position();
			for (int t = 0; t < 100 && (goal - d.position()).norm() < far; t++)
				goal = planner.regionCell(rng.drawUniform32bit() % planner.regionSize());
			if ((goal - d.position()).norm() < 1e-9)
				throw core::Error("trajectory: explore finds nowhere to go (the robot fits in one place only)");
			driveTo(d, planner, goal);
		}
		else
		{
			const bool backwards = s.kind == TrajectorySpec::Kind::Lawnmower && pass % 2 == 1;
			for (size_t i = 1; i < pattern.size() && !d.full(); i++)
				driveAlong(d, planner, pattern[backwards ? pattern.size() - 1 - i : i]);
			if (s.kind == TrajectorySpec::Kind::Loop && !d.full()) d.turnTowards(heading, true);
		}
		if (d.poses().size() == before)
			throw core::Error("trajectory: the pattern does not move the robot (arena too small for it?)");
	}
	// Guaranteed by PathPlanner; checked against the simulator's own test all the same.
	const WhiskerSimulator sim(w, robot, {}, 1);
	for (const auto& p : d.poses())
		if (!sim.poseIsFree(p)) throw core::Error("trajectory: internal error, a generated pose is blocked");
	return std::move(d.poses());
}
}  // namespace whiskermap::world
