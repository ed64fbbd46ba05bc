#pragma once

namespace whiskermap::eval
{
/** Gates and parameters of the ground-truth evaluation (doc/evaluation.md explains each
 *  default). */
struct EvalOptions
{
	/** An estimated and a true table may be matched only when their centres are at most this
	 *  far apart (metres): a quarter of the paper table's 1.0 m leg spacing, well above the
	 *  centre errors of a table located from its legs, well below the gap between tables. */
	double gate_distance = 0.25;
	/** ... and their yaws differ by at most this, modulo 180 degrees (a table is the same
	 *  table turned half a turn). */
	double gate_yaw_deg = 20;
	/** OSPA cut-off c (metres): the cost of a missing or extra table. */
	double ospa_c = 0.5;
	/** OSPA order p (>= 1); 1 makes OSPA a mean per-table error. */
	double ospa_p = 1;
	/** Per-pose "local" truth: the tables whose centre is within this distance (metres) of the
	 *  pose's robot position. */
	double local_radius = 1.5;
	/** Relative pose error: segments of at least this much true travel (metres). */
	double rpe_segment_m = 1.0;
	/** Walls (issue 11): a point of one wall's centre line is covered by another wall whose
	 *  centre line passes within this distance (metres), directions within gate_yaw_deg:
	 *  half a wall's 0.1 m thickness plus 0.1 m of error. Last: the Python bindings build
	 *  the options positionally. */
	double wall_gate = 0.15;

	/** Throws core::Error naming the first option out of range. */
	void validate() const;
};
}  // namespace whiskermap::eval
