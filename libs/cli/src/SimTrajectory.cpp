#include <CLI/CLI.hpp>
#include <whiskermap/cli/SimTrajectory.h>
#include <whiskermap/core/Angles.h>
#include <whiskermap/core/Error.h>
#include <whiskermap/world/Trajectory.h>


namespace whiskermap::cli
{
using namespace whiskermap::world;

void SimTrajectory::add(CLI::App& app)
{
	auto* trajectory = app.add_option(
		   "--trajectory", kind,
		   "paper-grid: N x N positions x 4 compass headings over the arena (a position where the "
		   "body would overlap a leg or wall is skipped, by design); lawnmower: back and forth "
		   "in rows --spacing apart; explore: random exploration from free place to free place; "
		   "wall-follow: round the arena --standoff from the walls; loop: a random closed tour "
		   "that ends at its start pose. The continuous ones step --speed/--rate metres, turn "
		   "at most --turn-rate, and drive round legs")
		->check(CLI::IsMember({"paper-grid", "lawnmower", "explore", "wall-follow", "loop"}))
		->capture_default_str();
	m_grid = app.add_option("--grid", grid, "N for paper-grid: N x N positions per tile (default 10: 400 poses per tile)")
		->check(CLI::Range(1, 1000))
		->capture_default_str();
	app.add_option(
		   "--path", path,
		   "Pose file, one 'x y yaw_deg' per line (instead of --trajectory); a pose where the "
		   "body would overlap a leg or wall is an error naming the line")
		->check(CLI::ExistingFile)
		->excludes(trajectory);
	m_continuousOnly.clear();
	auto continuousOnly = [this](CLI::Option* o) {
		m_continuousOnly.push_back(o);
		return o;
	};
	continuousOnly(app.add_option("--speed", spec.speed, "Continuous trajectories: speed, m/s"))
		->check(CLI::Range(1e-3, 10.0))
		->capture_default_str();
	app.add_option(
		   "--rate", rate,
		   "Whisk rate, sweeps per second (timestamps 1/rate s apart; default 8 for continuous "
		   "trajectories, 1 for paper-grid and --path)")
		->check(CLI::Range(1e-3, 1000.0));
	continuousOnly(app.add_option("--turn-rate", spec.turn_rate_deg, "Continuous trajectories: largest turn, degrees per second"))
		->check(CLI::Range(1e-3, 3600.0))
		->capture_default_str();
	continuousOnly(app.add_option(
					   "--duration", spec.duration,
					   "Continuous trajectories: stop after this many seconds (a pattern repeats until "
					   "then; explore: default 120 s)"))
		->check(CLI::Range(1e-3, 1e6));
	continuousOnly(app.add_option("--length", spec.length, "Continuous trajectories: stop after this many metres travelled"))
		->check(CLI::Range(1e-3, 1e6));
	continuousOnly(app.add_option("--spacing", spec.spacing, "lawnmower: distance between rows, m"))
		->check(CLI::Range(0.01, 100.0))
		->capture_default_str();
	continuousOnly(app.add_option("--standoff", spec.standoff, "lawnmower and wall-follow: robot centre to walls, m"))
		->check(CLI::Range(0.0, 100.0))
		->capture_default_str();
}

SimTrajectory::Poses SimTrajectory::poses(const WhiskerSimulator& sim, int tilesX, int tilesY, uint64_t seed) const
{
	const bool continuous = path.empty() && kind != "paper-grid";
	for (const auto* o : m_continuousOnly)
		if (!continuous && o->count() > 0)
			throw core::Error(o->get_name() + " applies to the continuous trajectories (lawnmower, explore, wall-follow, loop)");
	if ((continuous || !path.empty()) && m_grid && m_grid->count() > 0)
		throw core::Error("--grid applies to --trajectory paper-grid");
	Poses out;
	if (!path.empty())
	{
		// Checked whole (syntax, then every pose free) before anything is simulated.
		out.source = Trajectory::pathFileSource(path);
		for (mrpt::poses::CPose2D p; out.source->next(p);)
			if (!sim.poseIsFree(p))
				throw core::Error(
					out.source->where() + "pose (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
					std::to_string(core::rad2deg(p.phi())) +
					" deg) is blocked: the robot body would overlap a leg or wall");
		out.source->rewind();
		out.rate = rate > 0 ? rate : 1;
		return out;
	}
	if (kind == "paper-grid")
	{
		out.source = Trajectory::paperGridSource(sim.world(), grid * tilesX, grid * tilesY);
		out.skipBlocked = true;
		out.rate = rate > 0 ? rate : 1;
		return out;
	}
	TrajectorySpec s = spec;
	s.kind = TrajectorySpec::parseKind(kind);
	if (rate > 0) s.rate = rate;
	out.source = Trajectory::vectorSource(TrajectoryGenerator::generate(sim.world(), sim.robot(), s, seed));
	out.rate = s.rate;
	return out;
}
}  // namespace whiskermap::cli
