#pragma once
#include <whiskermap/eval/ClassFigures.h>
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/Figures.h>
#include <whiskermap/world/Table.h>

#include <optional>
#include <vector>

namespace whiskermap::eval
{
/** An estimated set of tables scored against the true tables: an optimal one-to-one matching
 *  (Hungarian, cost = centre distance) among the pairs of the same class within the centre
 *  and yaw gates, the figures over it, and OSPA of the centres. The centre gate scales with
 *  the true object's size (gate_distance for the paper's 1.0 x 0.6 m table); a square true
 *  object compares yaws modulo 90 degrees, others modulo 180. */
struct MapEvaluation
{
	size_t estimated = 0, truth = 0, matched = 0;
	Figures figures;
	/** For each true table, the index of its matched estimated table, or -1. */
	std::vector<int> truthMatch;
	/** Class accuracy and dimension errors, when the estimate carries classes. */
	std::optional<ClassFigures> classes;

	/** Throws core::Error when `opts` is out of range. */
	static MapEvaluation compute(
		const std::vector<world::Table>& truth, const std::vector<world::Table>& estimated,
		const EvalOptions& opts, bool estimateHasClasses = false);

	/** The centre gate of a true object: gate_distance times its leg-centre diagonal over
	 *  the paper table's (hypot(1.0, 0.6) m). */
	static double gateFor(const world::Table& truth, const EvalOptions& opts);
	/** The estimate's signed yaw error against the truth, radians: the estimate described
	 *  like the truth (sides swapped and turned by 90 degrees when that is closer) and
	 *  compared modulo its symmetry (90 degrees when either is square, else 180). */
	static double yawError(const world::Table& truth, const world::Table& estimated);
};
}  // namespace whiskermap::eval
