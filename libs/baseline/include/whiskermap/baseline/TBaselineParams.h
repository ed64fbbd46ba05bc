#pragma once
#include <string>

namespace whiskermap::baseline
{
/** Parameters of the batch geometric fit (doc/baseline.md explains each default). The known
 *  table comes from the model section of a whisker-map configuration; the rest are fixed
 *  rules of the baseline, scaled by the reading noise each sweep reports. SI units. */
struct TBaselineParams
{
	// The known table (model::ModelParams: table_length, table_width, leg_width, texture).
	double table_length = 1.0;  ///< leg-centre spacing along the table, metres
	double table_width = 0.6;  ///< leg-centre spacing across the table, metres
	double leg_width = 0.05;  ///< side of a square leg, metres
	double texture = 0.7;  ///< texture of table legs

	// Noise floors: what the fit assumes on top of the reported reading noise.
	double position_floor = 0.002;  ///< metres, on a contact's distance to its face
	double angle_floor = 0.0175;  ///< radians (1 degree), on a contact's normal
	double texture_floor = 0.02;  ///< texture units, added to sigma_tau

	// Rules.
	double texture_gate = 3;  ///< a contact's texture is within this many sigma_tau (with the floor) of the table's
	double texture_evidence = 2.3;  ///< nats (x10): a leg's textures favour the table's over any texture by this much
	double outlier_gate = 4;  ///< a contact further than this many sigmas from its leg's face is an outlier
	double outlier_fraction = 0.1;  ///< a leg-shaped cluster has at most this fraction of outliers
	double link_distance = 0.8;  ///< single-linkage radius, in leg widths (+ 2 sigma_r)
	double spacing_tolerance = 0.02;  ///< metres, added to 3 sigma of a leg pair's spacing
	double angle_tolerance = 0.14;  ///< radians (8 degrees): leg yaws vs the table's, modulo 90 degrees
	double free_margin = 0.01;  ///< metres: a predicted leg swept through by this much is contradicted

	// Bounded memory (BatchInput): a uniform sample per cell once a cell has received more.
	size_t contacts_per_cell = 512;  ///< contacts kept per square cell of one leg width
	size_t sectors_per_cell = 4096;  ///< swept sectors kept per FreeSpace cell (by pivot)

	/** The known table from the [MetricMap_hierarchicalObjectMap_00_model] section of a
	 *  whisker-map .ini (model::ModelParams, read strictly); built-in defaults when the file
	 *  has no such section, as for whisker-map. Throws core::Error naming the file when it is
	 *  missing, malformed, has no [MetricMap] section or a bad model key. */
	static TBaselineParams fromConfig(const std::string& path);
};
}  // namespace whiskermap::baseline
