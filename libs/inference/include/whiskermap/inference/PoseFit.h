#pragma once
#include <whiskermap/model/Blackboard.h>
#include <whiskermap/model/Leg.h>
#include <whiskermap/model/LegEvidence.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/model/Table.h>
#include <whiskermap/obs/Shapelet.h>

#include <cstddef>
#include <cstdint>

namespace whiskermap::inference
{
/** Closed-form pose fits: minimisers of the quadratic parts of eqs. 6-7. Shared by the exact
 *  oracle (doc/oracle.md) and the sampler's refit and pair-table moves (doc/sampler.md). */

/** The normal equations of a leg centre's least squares, in units of 1/sigma_r^2:
 *  A = (a11 a12; a12 a22), b = (b1, b2). */
struct CentreEquations
{
	double a11 = 0, a12 = 0, a22 = 0, b1 = 0, b2 = 0;
};

/** Adds eq. 7's quadratic part in a leg's centre for a leg at yaw `theta` (side leg_width):
 *  each contact on the line of the face whose outward normal matches its own, weighted by
 *  sigma_r^2 / its variance across that face (1 without shaft noise), and the folded
 *  `evidence` (may be null); `w` the leg's side. */
void addCentreEquations(
	const model::ModelParams& p, const obs::Shapelet* const* contacts, size_t n, double theta,
	const model::LegEvidence* evidence, CentreEquations& eq, double w);

/** The square leg (side: table t's leg width, else leg_width) best explaining `n` contacts, each on the face whose
 *  outward normal matches its own, optionally under table `t`: yaw = mean of the normals'
 *  (and the table's) yaws modulo 90 deg; centre = least squares of "each contact on its
 *  face line" plus "near (qx, qy)" with weight `pull` (a table corner: ModelParams::cornerPull;
 *  tiny: only fixes the position along a face), then moved along each face so that the face
 *  stays the contact's nearest (not beyond its end; for a contact inside the leg, nearer
 *  its centre than the contact's depth). Texture: mean of the contacts' and the table's.
 *  `evidence` (may be null): folded contacts of the leg, weighted as the contacts they
 *  stand for (their yaw and face-line terms join the means and the least squares). */
model::Leg fitLeg(
	const model::ModelParams& p, const obs::Shapelet* const* contacts, size_t n, const model::Table* t,
	double qx, double qy, double pull, const model::LegEvidence* evidence = nullptr);

/** The table of the known size (leg width and texture of `start`) best fitting `n` >= 1 legs
 *  standing at `corners` (eq. 6, positions and yaws): yaw = the rigid (Procrustes) fit of
 *  the corners to the leg centres, combined with the legs' yaws (mod 90 deg) in proportion
 *  to their curvatures; centre = the corners' mean onto the legs' mean. With one leg the
 *  yaw is the leg's, taken modulo 90 deg nearest to start.theta. */
model::Table fitTable(
	const model::ModelParams& p, const model::Table& start, const model::Leg* const* legs, const int* corners,
	size_t n);

/** The size and centre of `start` (its yaw kept) best fitting `n` >= 1 legs standing at
 *  `corners` under eq. 6's corner noise and eq. 24's size prior: along each of the table's
 *  axes, centre offset a and spacing b minimise
 *  sum_i (u_i - a - s_i b / 2)^2 / sigma_corner^2 + (b - b_k)^2 / size_sigma_k^2, with u_i a
 *  leg's coordinate along the axis, s_i = +-1 its corner's side and b_k the class's nominal
 *  spacing (a 2 x 2 linear system; legs on one side only leave b at b_k). Needs a catalogue. */
model::Table fitTableSize(
	const model::ModelParams& p, const model::Table& start, const model::Leg* const* legs, const int* corners,
	size_t n);

/** Greedy compass search over a leg's (x, y, yaw): moves of +-step in x and y and +-10 step
 *  (radians) in yaw, from a quarter of `legWidth` down to 0.1 mm, keeping any move that
 *  raises `score(leg)` by more than `tolerance`. `value` is score(leg) on entry; `leg`
 *  leaves as the best pose found, and its score is returned. Used where the closed forms
 *  above are not the whole score (the oracle's free legs, the sampler's polish). */
template <class Score>
double compassSearch(model::Leg& leg, double legWidth, double value, double tolerance, Score&& score)
{
	for (double step = legWidth / 4; step > 1e-4; step /= 2)
		for (bool improved = true; improved;)
		{
			improved = false;
			for (int k = 0; k < 6; k++)
			{
				model::Leg c = leg;
				(k < 2 ? c.x : k < 4 ? c.y : c.theta) += (k % 2 ? -1 : 1) * (k < 4 ? step : 10 * step);
				const double v = score(c);
				if (v > value + tolerance) value = v, leg = c, improved = true;
			}
		}
	return value;
}

/** compassSearch of leg `l`'s pose on its exact local log-odds (eq. 20: the rest of the board
 *  does not depend on its pose); the best pose is left on the board. Returns the gain (>= 0)
 *  and adds the poses it scored to `*evaluations` if given. Used by the sampler's polish and
 *  the exact oracle's rebuilt boards. */
double searchLegPose(model::Blackboard& bb, model::Id l, double tolerance, uint64_t* evaluations = nullptr);
}  // namespace whiskermap::inference
