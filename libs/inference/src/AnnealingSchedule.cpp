#include <whiskermap/core/Error.h>
#include <whiskermap/inference/AnnealingSchedule.h>

#include <cmath>

namespace whiskermap::inference
{
AnnealingSchedule::AnnealingSchedule(std::vector<double> betas) : m_betas(std::move(betas))
{
	if (m_betas.empty()) throw core::Error("AnnealingSchedule: no temperatures");
	for (size_t k = 0; k < m_betas.size(); k++)
		if (!(m_betas[k] > 0) || !std::isfinite(m_betas[k]) || (k > 0 && m_betas[k] < m_betas[k - 1]))
			throw core::Error("AnnealingSchedule: inverse temperatures must be positive, finite and non-decreasing");
}

AnnealingSchedule AnnealingSchedule::geometric(double beta0, double beta1, size_t steps)
{
	if (steps == 0) throw core::Error("AnnealingSchedule: steps must be at least 1");
	std::vector<double> b(steps, beta1);
	for (size_t k = 0; k + 1 < steps; k++)
		b[k] = beta0 * std::pow(beta1 / beta0, static_cast<double>(k) / static_cast<double>(steps - 1));
	return AnnealingSchedule(std::move(b));
}
}  // namespace whiskermap::inference
