#include <whiskermap/core/Angles.h>
#include <whiskermap/eval/MapEvaluation.h>
#include <whiskermap/eval/Ospa.h>
#include <whiskermap/eval/Se2Alignment.h>
#include <whiskermap/eval/SparseAssignment.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::eval
{
namespace
{
std::vector<Eigen::Vector2d> centres(const std::vector<world::Table>& tables)
{
	std::vector<Eigen::Vector2d> c;
	for (const auto& t : tables) c.emplace_back(t.x, t.y);
	return c;
}

/** `e` as the same rectangle described the other way round (length and width swapped, yaw
 *  turned by 90 degrees) when that description is closer to `t` in yaw (modulo 180 degrees)
 *  and its sides are no worse by more than SIDE_TOLERANCE (summed): a 0.43 x 0.41 chair at
 *  -90 degrees is a 0.41 x 0.43 chair at 0 (an inferred size makes near-square objects come
 *  either way), while a 1.0 x 0.6 table turned by 90 degrees stays another rectangle. */
world::Table orientedLike(const world::Table& e, const world::Table& t)
{
	constexpr double SIDE_TOLERANCE = 0.02;  // metres: the catalogue's size spread
	const double sides = std::abs(e.length - t.length) + std::abs(e.width - t.width);
	const double swappedSides = std::abs(e.width - t.length) + std::abs(e.length - t.width);
	const double yaw = std::abs(core::angleDiff(e.yaw, t.yaw, M_PI));
	const double swappedYaw = std::abs(core::angleDiff(e.yaw + M_PI_2, t.yaw, M_PI));
	if (swappedSides > sides + SIDE_TOLERANCE || swappedYaw >= yaw) return e;
	world::Table s = e;
	std::swap(s.length, s.width);
	s.yaw = core::wrapToPi(e.yaw + M_PI_2);
	return s;
}

/** The gated candidate pairs (row: true, column: estimated) and their yaw errors, degrees. */
struct Candidates
{
	std::vector<SparseAssignment::Pair> pairs;
	std::vector<double> yawErr;
};

Candidates candidates(
	const std::vector<world::Table>& truth, const std::vector<world::Table>& estimated, const EvalOptions& opts,
	bool sameClass)
{
	double widest = opts.gate_distance;  // the grid search radius: the widest per-object gate
	for (const auto& t : truth) widest = std::max(widest, MapEvaluation::gateFor(t, opts));
	Candidates c;
	for (const auto& p : SparseAssignment::near(centres(truth), centres(estimated), widest))
	{
		const auto& t = truth[p.row];
		const auto e = orientedLike(estimated[p.col], t);
		if (p.cost > MapEvaluation::gateFor(t, opts)) continue;
		if (sameClass && e.object_class != t.object_class) continue;
		const double yaw = core::rad2deg(std::abs(MapEvaluation::yawError(t, estimated[p.col])));
		if (yaw > opts.gate_yaw_deg) continue;
		c.pairs.push_back(p);
		c.yawErr.push_back(yaw);
	}
	return c;
}

ClassFigures classFigures(
	const std::vector<world::Table>& truth, const std::vector<world::Table>& estimated, const EvalOptions& opts,
	const std::vector<int>& truthMatch)
{
	ClassFigures f;
	const auto blind = candidates(truth, estimated, opts, false);
	const auto match = SparseAssignment::solve(int(truth.size()), int(estimated.size()), blind.pairs, INFINITY);
	size_t agree = 0;
	for (size_t i = 0; i < truth.size(); i++)
		if (match[i] >= 0) f.matched_any_class++, agree += estimated[match[i]].object_class == truth[i].object_class;
	if (f.matched_any_class > 0) f.class_accuracy = double(agree) / f.matched_any_class;
	double dl = 0, dw = 0, dlw = 0, blw = 0, dt = 0;
	size_t n = 0;
	for (size_t i = 0; i < truth.size(); i++)
	{
		if (truthMatch[i] < 0) continue;
		const auto& t = truth[i];
		const auto e = orientedLike(estimated[truthMatch[i]], t);
		dl += std::abs(e.length - t.length), dw += std::abs(e.width - t.width);
		dlw += std::abs(e.leg_width - t.leg_width), blw += e.leg_width - t.leg_width;
		dt += std::abs(e.texture - t.texture), n++;
	}
	if (n > 0)
		f.length_err_m = dl / n, f.width_err_m = dw / n, f.leg_width_err_m = dlw / n, f.leg_width_bias_m = blw / n,
		f.texture_err = dt / n;
	return f;
}
}  // namespace

double MapEvaluation::yawError(const world::Table& truth, const world::Table& estimated)
{
	const auto e = orientedLike(estimated, truth);
	// a square's symmetry: the truth's, or the estimate's (its yaw is then known modulo 90)
	const double period = truth.length == truth.width || e.length == e.width ? M_PI / 2 : M_PI;
	return core::angleDiff(e.yaw, truth.yaw, period);
}

double MapEvaluation::gateFor(const world::Table& truth, const EvalOptions& opts)
{
	// Exactly the option for the paper table (a hypot folded at compile time may differ from
	// the library's by an ulp: older scores must not move).
	if (truth.length == 1.0 && truth.width == 0.6) return opts.gate_distance;
	return opts.gate_distance * std::hypot(truth.length, truth.width) / std::hypot(1.0, 0.6);
}

MapEvaluation MapEvaluation::compute(
	const std::vector<world::Table>& truth, const std::vector<world::Table>& estimated,
	const EvalOptions& opts, bool estimateHasClasses)
{
	opts.validate();
	// Rows: true tables, columns: estimated ones; only pairs within the gates are scored (a
	// grid finds them), and the assignment is solved per connected component.
	const auto c = candidates(truth, estimated, opts, true);
	MapEvaluation e;
	e.estimated = estimated.size();
	e.truth = truth.size();
	e.truthMatch = SparseAssignment::solve(static_cast<int>(truth.size()), static_cast<int>(estimated.size()), c.pairs, INFINITY);
	double sumSq = 0, sumYaw = 0;
	std::vector<Eigen::Vector2d> from, to;  // the matched centres
	for (size_t k = 0; k < c.pairs.size(); k++)
	{
		const auto& p = c.pairs[k];
		if (e.truthMatch[p.row] != p.col) continue;
		e.matched++;
		sumSq += p.cost * p.cost;
		sumYaw += c.yawErr[k];
		from.emplace_back(estimated[p.col].x, estimated[p.col].y), to.emplace_back(truth[p.row].x, truth[p.row].y);
	}
	e.figures = Figures::of(
		e.estimated, e.truth, e.matched, sumSq, sumYaw,
		Ospa::distance(centres(estimated), centres(truth), opts.ospa_c, opts.ospa_p));
	if (from.size() >= 3)
	{
		const auto a = Se2Alignment::fit(from, to);
		double sq = 0;
		for (size_t i = 0; i < from.size(); i++) sq += (a.apply(from[i]) - to[i]).squaredNorm();
		e.figures.rmse_aligned_m = std::sqrt(sq / double(from.size()));
	}
	if (estimateHasClasses) e.classes = classFigures(truth, estimated, opts, e.truthMatch);
	return e;
}
}  // namespace whiskermap::eval
