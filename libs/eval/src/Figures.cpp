#include <whiskermap/eval/Figures.h>
#include <whiskermap/eval/FiguresMean.h>

namespace whiskermap::eval
{
Figures Figures::of(
	size_t estimated, size_t truth, size_t matched, double sumSqCentre, double sumYawDeg,
	double ospaValue)
{
	Figures f;
	f.precision = estimated ? double(matched) / estimated : 1.0;
	f.recall = truth ? double(matched) / truth : 1.0;
	const double pr = f.precision + f.recall;
	f.f1 = pr > 0 ? 2 * f.precision * f.recall / pr : 0.0;
	f.count_error = double(estimated) - double(truth);
	if (matched)
	{
		f.rmse_m = std::sqrt(sumSqCentre / matched);
		f.yaw_err_deg = sumYawDeg / matched;
	}
	f.ospa = ospaValue;
	return f;
}

void FiguresMean::add(const Figures& f)
{
	m_sum.precision += f.precision;
	m_sum.recall += f.recall;
	m_sum.f1 += f.f1;
	m_sum.count_error += f.count_error;
	m_sum.ospa += f.ospa;
	m_n++;
	if (!std::isnan(f.rmse_aligned_m)) m_aligned += f.rmse_aligned_m, m_alignedDefined++;
	if (std::isnan(f.rmse_m)) return;
	m_rmse += f.rmse_m;
	m_yaw += f.yaw_err_deg;
	m_defined++;
}

Figures FiguresMean::result() const
{
	if (!m_n) return {};
	Figures m = m_sum;
	const double n = double(m_n);
	m.precision /= n, m.recall /= n, m.f1 /= n, m.count_error /= n, m.ospa /= n;
	if (m_defined) m.rmse_m = m_rmse / m_defined, m.yaw_err_deg = m_yaw / m_defined;
	m.rmse_aligned_m = m_alignedDefined ? m_aligned / double(m_alignedDefined) : NAN;
	return m;
}

Figures Figures::mean(const std::vector<Figures>& items)
{
	FiguresMean m;
	for (const auto& f : items) m.add(f);
	return m.result();
}
}  // namespace whiskermap::eval
