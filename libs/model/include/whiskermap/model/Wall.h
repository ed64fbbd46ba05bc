#pragma once
#include <whiskermap/model/OrientedRect.h>

namespace whiskermap::model
{
/** A wall hypothesis W (issue 11; doc/model.md, "Walls"): a straight slab given by the end
 *  points of its centre line, its thickness and its texture. Its two long faces lie
 *  thickness/2 either side of the centre line; face +1 has the outward normal to the left of
 *  the direction (x0, y0) -> (x1, y1), face -1 to the right. It explains contacts on its long
 *  faces within its extent and on its two end caps (eq. 22). */
struct Wall
{
	double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< centre-line end points, metres (world frame)
	double thickness = 0;  ///< metres
	double texture = 0;  ///< in [0, 1]

	double length() const;
	/** Same end points, thickness and texture within `eps` (the closed-form fits are
	 *  deterministic to rounding, not to the bit). */
	bool sameAs(const Wall& o, double eps = 1e-9) const;
	/** True only when the point lies further than `d` from every point of the slab: outside
	 *  the centre line's bounding box grown by thickness / 2 + d (with a relative margin of
	 *  1e-9 for rounding). A cheap reject before the exact geometry below; false says nothing. */
	bool farFrom(double x, double y, double d) const;
	/** The slab as a rectangle (overlap with legs, eq. 16). */
	OrientedRect rect() const;

	/** Where a point lies relative to one long face. */
	struct FaceHit
	{
		int side;  ///< +1: the face to the left of the direction, -1: the right one
		double across;  ///< signed distance from that face's line, positive outside the slab
		double along;  ///< position along the centre line from (x0, y0), metres
		double excess;  ///< distance past the extent along the line (0 within [0, length])
		double normal;  ///< the face's outward normal angle, in (-pi, pi]
	};
	/** The centre line's length and unit direction (a degenerate wall points along x) and the
	 *  outward normal angle of each face: what every query below needs, computed once for
	 *  many points by the overloads taking it (a Blackboard keeps each wall's). */
	struct Frame
	{
		double len, ux, uy;
		double normal[4];  ///< per face of FACES (faceIndex), in (-pi, pi]
	};
	Frame frame() const;
	/** The point against face `side` (+1 or -1). */
	FaceHit face(double x, double y, int side) const { return face(frame(), x, y, side); }
	FaceHit face(const Frame& fr, double x, double y, int side) const;
	/** The point against any of the four faces: `f` = +1 or -1 a long face (as face()), +2 the
	 *  end cap at (x1, y1) (outward normal along the direction), -2 the one at (x0, y0). For a
	 *  cap, `across` is the signed distance from the cap's line (positive outside), `along` the
	 *  offset from the centre line and `excess` how far that offset exceeds thickness / 2. */
	FaceHit hit(double x, double y, int f) const { return hit(frame(), x, y, f); }
	FaceHit hit(const Frame& fr, double x, double y, int f) const;
	static constexpr int FACES[4] = {1, -1, 2, -2};
	/** The index of face `f` in FACES. */
	static constexpr int faceIndex(int f) { return 2 * ((f < 0 ? -f : f) - 1) + (f < 0); }
	/** The point against the face on its side of the centre line (the nearer face). */
	FaceHit nearestFace(double x, double y) const;
	/** Exact distance from the point to the face segment of `side`: hypot(across, excess). */
	double faceDistance(double x, double y, int side) const;
};
}  // namespace whiskermap::model
