#include <whiskermap/core/Angles.h>
#include <whiskermap/eval/WallEvaluation.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace whiskermap::eval
{
namespace
{
using Vec = Eigen::Vector2d;
using Interval = WallEvaluation::Interval;  // [lo, hi] of the parameter t, empty if lo > hi

/** The t (|d| = 1, p(t) = a + t d) where p(t) lies within r of the point c. */
Interval disc(const Vec& a, const Vec& d, const Vec& c, double r)
{
	const Vec ac = a - c;
	const double b = ac.dot(d), disc2 = b * b - (ac.squaredNorm() - r * r);
	if (disc2 < 0) return {1, 0};
	return {-b - std::sqrt(disc2), -b + std::sqrt(disc2)};
}

/** The t where p(t) lies within r of the segment s0-s1: the line meets the capsule around the
 *  segment (a convex set) in one interval, the union of its meets with the two end discs
 *  and the rectangle between them. */
Interval capsule(const Vec& a, const Vec& d, const Vec& s0, const Vec& s1, double r)
{
	Interval out = disc(a, d, s0, r);
	const Interval e = disc(a, d, s1, r);
	const auto merge = [&](const Interval& i) {
		if (i.first > i.second) return;
		out = out.first > out.second ? i : Interval{std::min(out.first, i.first), std::max(out.second, i.second)};
	};
	merge(e);
	// The rectangle: 0 <= (p - s0).u <= L and |(p - s0).n| <= r, clipped one slab at a time.
	const double L = (s1 - s0).norm();
	const Vec u = (s1 - s0) / L, n(-u.y(), u.x());
	Interval rect{-INFINITY, INFINITY};
	for (const auto& [axis, lo, hi] : {std::tuple{u, 0.0, L}, std::tuple{n, -r, r}})
	{
		const double p0 = (a - s0).dot(axis), rate = d.dot(axis);
		if (std::abs(rate) < 1e-15)
		{
			if (p0 < lo || p0 > hi) rect = {1, 0};
			continue;
		}
		const double t0 = (lo - p0) / rate, t1 = (hi - p0) / rate;
		rect = {std::max(rect.first, std::min(t0, t1)), std::min(rect.second, std::max(t0, t1))};
	}
	merge(rect);
	return out;
}

double direction(const world::Wall& w)
{
	return std::atan2(w.y1 - w.y0, w.x1 - w.x0);
}
}  // namespace

WallEvaluation::Intervals WallEvaluation::coveredIntervals(
	const world::Wall& wall, const std::vector<world::Wall>& others, double gate, double gateYawDeg)
{
	const Vec a(wall.x0, wall.y0);
	const double L = wall.length();
	const Vec d = (Vec(wall.x1, wall.y1) - a) / L;
	Intervals parts;
	for (const auto& o : others)
	{
		if (core::rad2deg(std::abs(core::angleDiff(direction(o), direction(wall), M_PI))) > gateYawDeg) continue;
		const Interval i = capsule(a, d, {o.x0, o.y0}, {o.x1, o.y1}, gate);
		const double lo = std::max(0.0, i.first), hi = std::min(L, i.second);
		if (lo < hi) unite(parts, lo, hi);
	}
	return parts;
}

double WallEvaluation::coveredLength(
	const world::Wall& wall, const std::vector<world::Wall>& others, double gate, double gateYawDeg)
{
	return length(coveredIntervals(wall, others, gate, gateYawDeg));
}

double WallEvaluation::length(const Intervals& a)
{
	double sum = 0;
	for (const auto& [lo, hi] : a) sum += hi - lo;
	return sum;
}

double WallEvaluation::overlap(const Intervals& a, const Intervals& b)
{
	double sum = 0;
	for (size_t i = 0, j = 0; i < a.size() && j < b.size();)
	{
		sum += std::max(0.0, std::min(a[i].second, b[j].second) - std::max(a[i].first, b[j].first));
		(a[i].second < b[j].second ? i : j)++;
	}
	return sum;
}

void WallEvaluation::unite(Intervals& a, double lo, double hi)
{
	auto first = std::lower_bound(a.begin(), a.end(), lo, [](const Interval& i, double x) { return i.second < x; });
	auto last = first;
	for (; last != a.end() && last->first <= hi; ++last) lo = std::min(lo, last->first), hi = std::max(hi, last->second);
	a.insert(a.erase(first, last), {lo, hi});
}

WallEvaluation WallEvaluation::compute(
	const std::vector<world::Wall>& truth, const std::vector<world::Wall>& estimated, double gate,
	double gateYawDeg, const std::vector<Intervals>* touched)
{
	WallEvaluation e;
	e.gate_m = gate;
	e.touched_known = touched != nullptr;
	for (size_t i = 0; i < truth.size(); i++)
	{
		const Intervals covered = coveredIntervals(truth[i], estimated, gate, gateYawDeg);
		e.true_length_m += truth[i].length(), e.true_covered_m += length(covered);
		if (!touched) continue;
		e.touched_length_m += length(touched->at(i));
		e.touched_covered_m += overlap(touched->at(i), covered);
	}
	if (e.touched_length_m > 0) e.recall_touched = e.touched_covered_m / e.touched_length_m;
	for (const auto& w : estimated)
		e.estimated_length_m += w.length(), e.estimated_covered_m += coveredLength(w, truth, gate, gateYawDeg);
	if (e.true_length_m > 0) e.recall = e.true_covered_m / e.true_length_m;
	if (e.estimated_length_m > 0) e.precision = e.estimated_covered_m / e.estimated_length_m;
	return e;
}

std::vector<world::Wall> WallEvaluation::trueWalls(const world::World& w)
{
	auto walls = w.walls;
	const double x[] = {w.x_min, w.x_max, w.x_max, w.x_min}, y[] = {w.y_min, w.y_min, w.y_max, w.y_max};
	for (int k = 0; k < 4; k++)
	{
		world::Wall edge;
		edge.x0 = x[k], edge.y0 = y[k], edge.x1 = x[(k + 1) % 4], edge.y1 = y[(k + 1) % 4];
		edge.texture = w.wall_texture;
		walls.push_back(edge);
	}
	return walls;
}
}  // namespace whiskermap::eval
