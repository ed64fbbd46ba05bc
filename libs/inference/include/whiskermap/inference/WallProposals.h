#pragma once
#include <whiskermap/model/Blackboard.h>

#include <optional>
#include <vector>

namespace whiskermap::inference
{
/** The data-driven wall proposal (doc/sampler.md, "Walls"): a Hough-style line from one
 *  contact. Each contact carries its surface normal, so one contact fixes a candidate face
 *  line (through it, perpendicular to its normal); its inliers are the board's shapelets
 *  within the parent gate of that line whose normals agree within 3 sigma_theta (both faces:
 *  normals opposite count on the far face), not linked to another wall, forming one run along
 *  the line with gaps of at most `wall_gap` (0.5 m) around the seed. The wall is the
 *  closed-form fit (WallEvidence::fit) to them. Deterministic given the seed. */
struct WallCandidate
{
	model::Wall wall;
	std::vector<model::Id> inliers;  ///< shapelet indices, ascending
};

/** The candidate seeded at shapelet `seed`, or nullopt when fewer than `minInliers` (3)
 *  shapelets agree. */
std::optional<WallCandidate> proposeWall(const model::Blackboard& bb, size_t seed, size_t minInliers = 3);

/** Wall `w` refitted to its shapelets and folded evidence (WallEvidence::fit); false if it
 *  explains nothing. */
bool fitWall(const model::Blackboard& bb, model::Id w, model::Wall& out);
}  // namespace whiskermap::inference
