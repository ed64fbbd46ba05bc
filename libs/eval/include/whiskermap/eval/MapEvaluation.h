#pragma once
#include <whiskermap/eval/EvalOptions.h>
#include <whiskermap/eval/Figures.h>
#include <whiskermap/world/Table.h>

#include <vector>

namespace whiskermap::eval
{
/** An estimated set of tables scored against the true tables: an optimal one-to-one matching
 *  (Hungarian, cost = centre distance) among the pairs within the centre and yaw gates, the
 *  figures over it, and OSPA of the centres. */
struct MapEvaluation
{
	size_t estimated = 0, truth = 0, matched = 0;
	Figures figures;
	/** For each true table, the index of its matched estimated table, or -1. */
	std::vector<int> truthMatch;

	/** Throws core::Error when `opts` is out of range. */
	static MapEvaluation compute(
		const std::vector<world::Table>& truth, const std::vector<world::Table>& estimated,
		const EvalOptions& opts);
};
}  // namespace whiskermap::eval
