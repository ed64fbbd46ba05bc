#include <whiskermap/eval/Figures.h>

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

Figures Figures::mean(const std::vector<Figures>& items)
{
	if (items.empty()) return {};
	Figures m;
	m.precision = m.recall = m.f1 = m.ospa = 0;
	double rmse = 0, yaw = 0;
	size_t defined = 0;
	for (const auto& f : items)
	{
		m.precision += f.precision;
		m.recall += f.recall;
		m.f1 += f.f1;
		m.count_error += f.count_error;
		m.ospa += f.ospa;
		if (std::isnan(f.rmse_m)) continue;
		rmse += f.rmse_m;
		yaw += f.yaw_err_deg;
		defined++;
	}
	const double n = double(items.size());
	m.precision /= n, m.recall /= n, m.f1 /= n, m.count_error /= n, m.ospa /= n;
	if (defined) m.rmse_m = rmse / defined, m.yaw_err_deg = yaw / defined;
	return m;
}
}  // namespace whiskermap::eval
