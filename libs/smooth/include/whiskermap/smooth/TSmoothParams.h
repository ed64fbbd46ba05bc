#pragma once
#include <cmath>
#include <string>

namespace whiskermap::smooth
{
/** The path smoother's settings: the [smooth] section of whisker-slam's .ini (doc/slam.md,
 *  "Smoothing the path"). Read strictly: unknown keys are errors naming the file. */
struct TSmoothParams
{
	bool enabled = true;  ///< smooth the best particle's path (off: the filter's path is the estimate)
	double gate = 0.04;  ///< metres: a contact is tied to the nearest face of a mapped solid within this
	double normal_gate = M_PI / 4;  ///< radians (key normal_gate_deg, 45): its normal within this of the face's
	double position_floor = 0.002;  ///< metres, added (in quadrature) to a contact's std-dev across its face
	double huber = 2;  ///< Huber's loss beyond this many std-devs (contacts)
	/** Metres: pieces of walls on parallel lines within this of each other are one wall
	 *  (WallLines; 0: every piece on its own). */
	double wall_merge = 0.1;
	/** Metres: std-dev of eq. S4, which holds a leg the map holds twice (DuplicateLegs) to one
	 *  place (0: duplicates are left alone). */
	double duplicate_sigma = 0.005;
	/** Metres: mapped tables (three legs touched) whose footprints, shrunk by this on every
	 *  side, overlap are one table. */
	double duplicate_shrink = 0.1;
	/** Metres: touched legs of two mapped tables whose centres lie this close are one leg. */
	double duplicate_distance = 0.08;
	/** Metres: parallel walls touched from the same side, overlapping along and at most this
	 *  far apart across, are one wall (DuplicateWalls; eq. S5; 0: never). */
	double duplicate_wall_distance = 0.3;
	double solid_sigma = 1;  ///< metres: prior std-dev of each solid's shift (walls slide along themselves)
	/** Metres: std-dev of eq. S7, which keeps the distance between two legs of one mapped table
	 *  (TableShapeFactor; 0: each leg free). */
	double table_sigma = 0;
	/** Std-devs: a window of `bridge_window` sweeps over which the smoothed path's motion
	 *  differs from the odometry's by more than this is a stray stretch, which the smoother
	 *  solves again from the odometry's own path across it (eq. S8, OdometryBridge; 0: never). */
	double bridge_gate = 4;
	unsigned bridge_window = 40;  ///< sweeps: the window of eq. S8
	/** Sweeps: a second, shorter window of eq. S8, whose strays are tried too (a bend that comes
	 *  back within bridge_window sweeps shows only in a shorter one; 0: none, the default:
	 *  doc/slam.md, "A short window beside the long one"). */
	unsigned bridge_short_window = 0;
	/** Sweeps: a pair set (a table or a wall mapped twice) that eq. S6 leaves apart is tried
	 *  again with the stretch of path that touched one copy moved onto the other, the move
	 *  fading over this many sweeps at its ends (eq. S9, ShiftedStretch; 0: never). */
	unsigned stretch_margin = 40;
	unsigned rounds = 6;  ///< association rounds (each re-ties the contacts, then solves)
	unsigned iterations = 10;  ///< Levenberg-Marquardt iterations per round, at most
	/** Smoothing passes: the first against the best particle's map, each further one against
	 *  a map built afresh at the previous pass's path. */
	unsigned passes = 2;

	/** Reads [smooth] from `path` (absent section or keys: the defaults). */
	static TSmoothParams load(const std::string& path);
};
}  // namespace whiskermap::smooth
