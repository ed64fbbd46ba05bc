#include <whiskermap/core/MathCache.h>
#include <whiskermap/model/Factors.h>

#include <cmath>

namespace whiskermap::model
{
double logMissingLegs(int missing, const ModelParams& p) { return missing * core::cachedLog(p.epsilon); }  // eq. 15
double logSameCorner(int pairs, const ModelParams& p) { return pairs * core::cachedLog(p.epsilon); }  // eq. 17
double logOverlap(int pairs, const ModelParams& p) { return pairs * core::cachedLog(p.epsilon); }  // eq. 16

double logTableConstraints(const CornerCounts& counts, const ModelParams& p)
{
	int missing = 0, pairs = 0;
	for (const int k : counts)
	{
		missing += k == 0;
		pairs += k * (k - 1) / 2;
	}
	return logMissingLegs(missing, p) + logSameCorner(pairs, p);
}
}  // namespace whiskermap::model
