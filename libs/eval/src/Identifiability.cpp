#include <whiskermap/eval/Identifiability.h>

#include <algorithm>
#include <bitset>
#include <cmath>

namespace whiskermap::eval
{
double Identifiability::defaultGate(const std::vector<obs::RawlogReader::Sweep>& sweeps)
{
	double sigma = 0;
	for (const auto& s : sweeps) sigma = std::max(sigma, s.obs->noise.sigma_r);
	return gateFor(sigma);
}

namespace
{
int64_t cellKey(int64_t ix, int64_t iy) { return static_cast<int64_t>((static_cast<uint64_t>(ix) << 32) ^ static_cast<uint32_t>(iy)); }
int64_t cellOf(double v, double cell) { return static_cast<int64_t>(std::clamp(std::floor(v / cell), -1e15, 1e15)); }
}  // namespace

Identifiability::Accumulator::Accumulator(const world::World& world, double gate)
	: m_world(world), m_gate(gate), m_touched(world.tables.size())
{
	// Cells as large as the largest table's reach (plus the gate): a contact's own cell and
	// its 8 neighbours hold every table it may be on.
	double reach = 0;
	for (const auto& t : world.tables) reach = std::max(reach, std::hypot(t.length + t.leg_width, t.width + t.leg_width) / 2);
	m_cell = std::max(reach + gate, 1e-3);
	for (uint32_t i = 0; i < world.tables.size(); i++)
		m_grid[cellKey(cellOf(world.tables[i].x, m_cell), cellOf(world.tables[i].y, m_cell))].push_back(i);
}

void Identifiability::Accumulator::add(const obs::RawlogReader::Sweep& sweep)
{
	for (const auto& s : sweep.obs->toShapelets(sweep.robotPose))
	{
		const int64_t cx = cellOf(s.x, m_cell), cy = cellOf(s.y, m_cell);
		for (int64_t dx = -1; dx <= 1; dx++)
			for (int64_t dy = -1; dy <= 1; dy++)
			{
				const auto it = m_grid.find(cellKey(cx + dx, cy + dy));
				if (it == m_grid.end()) continue;
				for (const uint32_t t : it->second)
					for (int k = 0; k < 4; k++)
						if (m_world.tables[t].leg(k, int(t)).distance({s.x, s.y}) <= m_gate) m_touched[t].set(k);
			}
	}
}

Identifiability Identifiability::Accumulator::result() const
{
	Identifiability id;
	id.gate = m_gate;
	for (size_t t = 0; t < m_touched.size(); t++)
		if (m_touched[t].count() >= 2) id.tables.push_back(t);
	return id;
}

Identifiability Identifiability::of(
	const world::World& world, const std::vector<obs::RawlogReader::Sweep>& sweeps, double gate)
{
	Accumulator acc(world, gate);
	for (const auto& s : sweeps) acc.add(s);
	return acc.result();
}

double Identifiability::recall(const MapEvaluation& e) const
{
	if (tables.empty()) return 1.0;
	const auto found = std::count_if(
		tables.begin(), tables.end(), [&](size_t t) { return e.truthMatch.at(t) >= 0; });
	return double(found) / double(tables.size());
}
}  // namespace whiskermap::eval
