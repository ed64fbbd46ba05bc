#pragma once
#include <whiskermap/model/ModelParams.h>

#include <array>

namespace whiskermap::model
{
/** The constraint factors of the factor graph (eq. 14, paper section 4), as logarithms. */

/** phi_a = epsilon^m, m = the table's number of missing legs (eq. 15). */
double logMissingLegs(int missing, const ModelParams& p);

/** phi_b = epsilon^r, r = 1 for a pair of legs with the same parent and corner (eq. 17). */
double logSameCorner(int pairs, const ModelParams& p);

/** phi_c = epsilon^v, v = 1 for a pair of overlapping objects of the same type (eq. 16). */
double logOverlap(int pairs, const ModelParams& p);

/** Number of child legs of one table at each of its corners. */
using CornerCounts = std::array<int, 4>;

/** All factors a table owns given its children: phi_a (eq. 15) times phi_b (eq. 17) over
 *  every pair of its legs sharing a corner. */
double logTableConstraints(const CornerCounts& counts, const ModelParams& p);
}  // namespace whiskermap::model
