#include <whiskermap/inference/RandomScan.h>

#include <cmath>
#include <numeric>

namespace whiskermap::inference
{
size_t RandomScan::add(ScanMove m)
{
	m_moves.push_back(std::move(m));
	m_proposed.push_back(0);
	m_accepted.push_back(0);
	return m_moves.size() - 1;
}

size_t RandomScan::step(moves::MoveContext& ctx)
{
	const double total =
		std::accumulate(m_moves.begin(), m_moves.end(), 0.0, [](double s, const ScanMove& m) { return s + m.weight; });
	double u = ctx.rng.uniform() * total;
	size_t i = 0;
	while (i + 1 < m_moves.size() && u >= m_moves[i].weight) u -= m_moves[i++].weight;
	ScanMove& m = m_moves[i];
	std::optional<moves::Proposal> p = m.propose(ctx);
	if (!p) return i;
	p->logForward += std::log(m.weight / total);
	p->logReverse += std::log(m_moves[m.reverse].weight / total);
	const bool yes = ctx.accept(*p);
	m.finish(ctx, yes);
	m_proposed[i]++;
	m_accepted[i] += yes;
	return i;
}
}  // namespace whiskermap::inference
