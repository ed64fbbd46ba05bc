#pragma once
#include <whiskermap/core/Angles.h>
#include <whiskermap/model/HypothesisSet.h>
#include <whiskermap/model/ModelParams.h>
#include <whiskermap/obs/Shapelet.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace whiskermap::inference
{
/** Resolution and limits of the exact MAP oracle (doc/oracle.md). */
struct OracleOptions
{
	double grid_step = 0.01;  ///< table centres on a world grid of this step, metres
	double yaw_step = core::deg2rad(1);  ///< table yaws k * yaw_step in [0, pi), radians
	int max_tables = 2;  ///< 0, 1 or 2 tables per configuration
	size_t max_shapelets = 8;  ///< larger problems throw (the search is exponential in them)
};

/** What the oracle found: the best configuration and how much it looked at. */
struct OracleResult
{
	model::HypothesisSet map;  ///< tables, legs and shapelet links of the optimum
	double logPosterior = -std::numeric_limits<double>::infinity();  ///< logJoint (eq. 14) of `map`
	size_t configurationsScored = 0;  ///< table sets whose best completion was computed
	size_t boardsScored = 0;  ///< improving completions rebuilt as a Blackboard, scored by logJoint
	/** The search's own sum of the eq. 14 terms equalled logJoint of every board it rebuilt
	 *  (1e-6): the decomposition the search ranks by is the model's. */
	bool certified = true;
};

/** Brute-force MAP (eq. 18) of one time step, for checking the sampler: every table set of
 *  0..max_tables tables on a (x, y, yaw) grid, every partition of the shapelets into legs,
 *  every link of a leg to a table corner or to no table, invented or missing legs at empty
 *  corners; leg poses solved per link. Candidates are ranked by the additive terms of eq. 14
 *  and the best is rebuilt as a model::Blackboard and scored by model::logJoint. Works in the
 *  sampler's gated space: links only within ModelParams::parent_gate (doc/oracle.md says
 *  exactly what is exhaustive and what is bounded). Slow by design; const and thread-safe. */
class ExactMapOracle
{
   public:
	/** Throws std::invalid_argument if the parameters break the pruning argument (a table
	 *  whose shapelet-explaining legs all sit at one corner must never pay off). */
	explicit ExactMapOracle(const model::ModelParams& model, const OracleOptions& options = {});

	OracleResult solve(const std::vector<obs::Shapelet>& shapelets) const;

	const OracleOptions& options() const { return m_options; }

   private:
	model::ModelParams m_model;
	OracleOptions m_options;
};
}  // namespace whiskermap::inference
