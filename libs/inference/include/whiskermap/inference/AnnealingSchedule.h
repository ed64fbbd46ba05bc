#pragma once
#include <vector>

namespace whiskermap::inference
{
/** The inverse temperatures beta of Algorithm 1, hottest (smallest) first. The sampler's
 *  MAP is taken at the last (coldest) one. */
class AnnealingSchedule
{
   public:
	/** Throws core::Error unless `betas` is non-empty, positive, finite and non-decreasing. */
	explicit AnnealingSchedule(std::vector<double> betas);

	/** `steps` values from beta0 to beta1 in equal ratios (steps == 1: just beta1). */
	static AnnealingSchedule geometric(double beta0, double beta1, size_t steps);

	const std::vector<double>& betas() const { return m_betas; }
	size_t size() const { return m_betas.size(); }
	double operator[](size_t k) const { return m_betas[k]; }

   private:
	std::vector<double> m_betas;
};
}  // namespace whiskermap::inference
