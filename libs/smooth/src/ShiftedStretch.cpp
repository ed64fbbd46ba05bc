#include <whiskermap/smooth/ShiftedStretch.h>

#include <algorithm>
#include <limits>
#include <map>

namespace whiskermap::smooth
{
bool ShiftedStretch::move(
	std::vector<Eigen::Vector3d>& path, std::vector<Eigen::Vector2d>& shifts, const std::vector<ContactFactor>& ties,
	const std::vector<SameSolidFactor>& set, bool bSide, size_t margin)
{
	if (set.empty() || path.size() < 2) return false;
	// Each copy's move onto its twin (zeroing eqs. S4-S5's residual), and t, their mean.
	std::map<size_t, Eigen::Vector2d> moved;
	std::vector<bool> twin(shifts.size(), false);
	Eigen::Vector2d t = Eigen::Vector2d::Zero();
	for (const auto& f : set)
	{
		const Eigen::Vector2d gap = f.P * (f.offset + shifts[f.a] - shifts[f.b]);  // b's move onto a
		moved[bSide ? f.b : f.a] = bSide ? gap : Eigen::Vector2d(-gap);
		twin[bSide ? f.a : f.b] = true;
		t += bSide ? gap : Eigen::Vector2d(-gap);
	}
	t /= static_cast<double>(set.size());
	// The stretch: the sweeps that touched the moved copies.
	size_t first = std::numeric_limits<size_t>::max(), last = 0;
	for (const auto& f : ties)
		if (moved.count(f.group)) first = std::min(first, f.pose), last = std::max(last, f.pose);
	if (first > last) return false;
	// Groups touched only within the stretch were mapped by it, and move with it.
	std::vector<int> inside(shifts.size(), -1);  // -1 untouched, 1 only within, 0 also outside
	for (const auto& f : ties)
	{
		const bool in = f.pose >= first && f.pose <= last;
		inside[f.group] = inside[f.group] == -1 ? in : (inside[f.group] == 1 && in);
	}
	for (size_t g = 0; g < shifts.size(); g++)
		if (const auto it = moved.find(g); it != moved.end())
			shifts[g] += it->second;
		else if (inside[g] == 1 && !twin[g])
			shifts[g] += t;
	const size_t n = path.size(), begin = first > margin ? first - margin : 0;
	const size_t end = last + margin >= n - 1 ? n : last + margin;  // n: the stretch runs to the path's end
	for (size_t i = std::max<size_t>(begin, 1); i < n && i <= end; i++)
	{
		double w = 1;  // eq. S9's weight
		if (i < first) w = static_cast<double>(i - begin) / static_cast<double>(first - begin);
		else if (i > last && end < n) w = static_cast<double>(end - i) / static_cast<double>(end - last);
		path[i].head<2>() += w * t;
	}
	return true;
}
}  // namespace whiskermap::smooth
