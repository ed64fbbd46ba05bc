#include <whiskermap/core/Angles.h>
#include <whiskermap/inference/WallProposals.h>
#include <whiskermap/model/Densities.h>

#include <algorithm>
#include <cmath>

namespace whiskermap::inference
{
using model::Id;

namespace
{
constexpr double WALL_GAP = 0.5;  ///< largest gap (m) between neighbouring contacts of one wall run
}  // namespace

std::optional<WallCandidate> proposeWall(const model::Blackboard& bb, size_t seed, size_t minInliers)
{
	const model::ModelParams& p = bb.params();
	const obs::Shapelet& s0 = bb.shapelets()[seed];
	const double nx = std::cos(s0.normal), ny = std::sin(s0.normal), ux = ny, uy = -nx;
	// The seed's face line: n . q = n . s0; the far face lies one wall thickness behind it.
	std::vector<std::pair<double, Id>> along;
	for (size_t i = 0; i < bb.shapelets().size(); i++)
	{
		const obs::Shapelet& s = bb.shapelets()[i];
		const Id w = bb.shapeletWall(i);
		if (w != model::NONE && w != bb.shapeletWall(seed)) continue;
		const double off = nx * (s.x - s0.x) + ny * (s.y - s0.y);
		const double err = core::wrapToPi(s.normal - s0.normal);
		const bool near = std::abs(off) <= p.parent_gate && std::abs(err) <= 3 * p.sigma_theta;
		const bool far = std::abs(off + p.wall_thickness) <= p.parent_gate &&
						 std::abs(core::wrapToPi(err - M_PI)) <= 3 * p.sigma_theta;
		if (near || far) along.emplace_back(ux * (s.x - s0.x) + uy * (s.y - s0.y), static_cast<Id>(i));
	}
	std::sort(along.begin(), along.end());
	// The run around the seed (at along = 0) with gaps of at most WALL_GAP.
	size_t at = 0;
	while (along[at].second != static_cast<Id>(seed)) at++;
	size_t lo = at, hi = at;
	while (lo > 0 && along[lo].first - along[lo - 1].first <= WALL_GAP) lo--;
	while (hi + 1 < along.size() && along[hi + 1].first - along[hi].first <= WALL_GAP) hi++;
	if (hi - lo + 1 < minInliers) return std::nullopt;
	WallCandidate c;
	model::Wall guide;  // the seed's line, to put each inlier on its face
	guide.thickness = p.wall_thickness;
	guide.x0 = s0.x - nx * p.wall_thickness / 2, guide.y0 = s0.y - ny * p.wall_thickness / 2;
	guide.x1 = guide.x0 + ux, guide.y1 = guide.y0 + uy;  // face +1 (left of u) has normal n
	const model::Wall::Frame fr = guide.frame();
	model::WallEvidence e;
	for (size_t k = lo; k <= hi; k++)
	{
		c.inliers.push_back(along[k].second);
		e.add(bb.shapelets()[static_cast<size_t>(along[k].second)], guide, fr, p);
	}
	std::sort(c.inliers.begin(), c.inliers.end());
	c.wall = e.fit(p.wall_thickness, p.wallAxis());
	return c;
}

bool fitWall(const model::Blackboard& bb, Id w, model::Wall& out)
{
	if (!bb.wallExplains(w)) return false;
	model::WallEvidence e = bb.wallEvidence(w);
	for (const Id s : bb.shapeletsOfWall(w)) e.add(bb.shapelets()[static_cast<size_t>(s)], bb.wall(w), bb.wallFrame(w), bb.params());
	out = e.fit(bb.params().wall_thickness, bb.params().wallAxis());
	return true;
}
}  // namespace whiskermap::inference
